// Sleep of torn pieces (issue 14): a piece torn off the cloth that has settled is not simulated
// until something can move it, while the rest of the cloth goes on (the World's own sleep,
// sleep.cpp, needs every particle at rest).
//
// Falling asleep, after a frame: the cloth has two pieces or more; the piece has no pinned and no
// driven particle (the cloth the pins hold is the World's sleep's business); every particle of it
// moved slower than sleep.speed in each of the last sleep.delay seconds of frames; no wind. Its
// particles then get kAsleep (cloth.h): inverse mass 0, like a pin, and velocity 0, so no phase
// moves them and the limit and the guard treat them as fixed.
// Waking, before a frame: sleep off; wind; any parameter changed since the last frame; a driver
// on one of its particles (the drag tool grabbing it); an awake ball whose reach over the frame
// overlaps the box of the sleeping particles; World::wake() (the knife, impulses, deleting a piece,
// tools).
// Every sleeping piece wakes at once: rare events, and no piece is left resting on one that moves.
#include "sleep.h"

#include "clothtear/pieces.h"
#include "step_context.h"

#include <algorithm>
#include <cmath>

namespace clothtear {
namespace {

bool anyAsleep(const Cloth& c) {
    for (uint8_t f : c.flags)
        if (f & kAsleep) return true;
    return false;
}

// The pieces as labels, rebuilt after a topology change; labelCount: how many pieces.
void refreshLabels(const Cloth& c, SleepState& S) {
    if (S.labelsTopology == c.topologyRevision && S.labels.size() == c.particleCount()) return;
    S.labels = pieceLabels(c);
    S.labelCount = 0;
    for (Index p = 0; p < S.labels.size(); ++p) S.labelCount += S.labels[p] == p;
    S.labelsTopology = c.topologyRevision;
}

} // namespace

void wakePieces(World& w, StepState& state) {
    Cloth& c = w.cloth;
    for (Index p = 0; p < c.particleCount(); ++p)
        if (c.asleep(p)) c.setAsleep(p, false);
    // Something moved the cloth from outside the step (or renumbered it: deleting a piece): every
    // particle starts counting its still frames again.
    state.sleep.stillFrames.clear();
}

void wakePiecesIfTouched(World& w, StepState& state) {
    const Cloth& c = w.cloth;
    const Settings& settings = w.settings;
    SleepState& S = state.sleep;
    if (!anyAsleep(c)) {
        S.pieceSettings = settings;
        return;
    }
    bool touched = !settings.sleep.enabled || windBlows(settings) || paramsChanged(settings, S.pieceSettings);
    for (const Driver& d : w.drivers)
        for (Index p : d.particles) touched |= p < c.particleCount() && c.asleep(p);
    if (!touched && !w.balls.empty()) {
        Vec3 lo = Vec3::Constant(1e30f), hi = Vec3::Constant(-1e30f);
        for (Index p = 0; p < c.particleCount(); ++p)
            if (c.asleep(p)) lo = lo.cwiseMin(c.x[p]), hi = hi.cwiseMax(c.x[p]);
        touched = aBallCanReach(w, lo, hi);
    }
    if (touched) wakePieces(w, state);
    S.pieceSettings = settings;
}

void updatePieceSleep(World& w, StepState& state) {
    Cloth& c = w.cloth;
    const Settings& settings = w.settings;
    SleepState& S = state.sleep;
    const size_t n = c.particleCount();
    S.stillFrames.resize(n, 0); // particles a tear added start moving
    if (!settings.sleep.enabled || !w.finite || windBlows(settings)) {
        std::fill(S.stillFrames.begin(), S.stillFrames.end(), uint16_t(0));
        return;
    }
    // Judged by how far each particle moved over the frame, as the World's sleep (sleep.cpp).
    const float step = settings.sleep.speed * settings.time.frameDt;
    const std::vector<Vec3>& x0 = S.frameStart;
    for (Index p = 0; p < n; ++p) {
        const bool still = p < x0.size() && (c.x[p] - x0[p]).squaredNorm() < step * step;
        S.stillFrames[p] = still ? uint16_t(std::min<int>(S.stillFrames[p] + 1, 0xffff)) : uint16_t(0);
    }
    refreshLabels(c, S);
    if (S.labelCount < 2) return;
    const int need = stillFramesToSleep(settings);
    // Per piece (indexed by its label): held by a pin or a driver, awake particles, fewest still frames.
    std::vector<uint8_t> held(n, 0), awake(n, 0);
    std::vector<uint16_t> fewest(n, 0xffff);
    for (const Driver& d : w.drivers)
        for (Index p : d.particles)
            if (p < n && S.labels[p] != kNone) held[S.labels[p]] = 1;
    for (Index p = 0; p < n; ++p) {
        const Index piece = S.labels[p];
        if (piece == kNone) continue;
        held[piece] |= c.pinned(p);
        awake[piece] |= !c.asleep(p);
        fewest[piece] = std::min(fewest[piece], S.stillFrames[p]);
    }
    for (Index p = 0; p < n; ++p) {
        const Index piece = S.labels[p];
        if (piece == kNone || held[piece] || !awake[piece] || fewest[piece] < need || c.asleep(p)) continue;
        c.setAsleep(p, true);
    }
}

} // namespace clothtear
