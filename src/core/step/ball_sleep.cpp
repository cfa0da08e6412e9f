// Sleep of balls: a ball at rest with no moving cloth within its reach is not simulated.
//
// Why: a thrown ball ends on the ground, often on the piece it tore out, and stays there. Awake, it
// kept the whole cloth in the step's mode for a ball near the cloth (the guard's per-spring caps: 76
// sub-steps a frame at 128 x 128 instead of the particle budget's 48), kept the piece under it and
// the World from sleeping, and paid the ball phases every sub-step: the 2 m curtain at 128 a side
// after the ball tool's default throw cost 27 ms a frame on one thread for as long as the ball lay
// there, 15 without the ball (bench/README.md, "Balls at rest sleep").
//
// Falling asleep, after a frame: sleep on, no driver, no wind; the ball moved slower than
// sleep.speed in each of the last sleep.delay seconds of frames (Ball::stillFrames); no free
// particle that is awake lies within its reach (its radius, the collision thickness and a mean rest
// length): what it rests on is the ground, pinned cloth or a piece asleep. A piece it rests on falls
// asleep in the frame (piece_sleep.cpp runs first) and the still ball with it. Its velocity becomes
// 0; the ball phases skip it, and it counts neither as a ball near the cloth (step.cpp) nor as one
// that can reach a sleeping cloth or piece (sleep.cpp).
// Waking, before a frame: sleep off, a driver, wind, any parameter changed since the last frame, a
// velocity given to it, an awake free particle within its reach grown by the distance the cloth's
// fastest particle moves in a frame (a piece woken under it, the curtain swinging into it),
// World::wake(). While the World sleeps (sleep.cpp), its awake balls, none of which can reach the
// cloth that frame, still fly and bounce on the ground (they used to hang where they were), and may
// fall asleep.
#include "sleep.h"

#include "collide.h"
#include "step_context.h"

#include <algorithm>
#include <cmath>

namespace clothtear {
namespace {

// Is a free particle (inverse mass > 0: not pinned, not asleep) within `reach` of the ball's
// surface, box-wise?
bool freeParticleWithin(const Cloth& c, const Ball& b, float reach) {
    const Eigen::Array3f lo = b.x.array() - (b.radius + reach), hi = b.x.array() + (b.radius + reach);
    for (Index p = 0; p < c.particleCount(); ++p) {
        if (c.invMass[p] == 0.f) continue;
        const Eigen::Array3f x = c.x[p].array();
        if (!((x < lo).any() || (x > hi).any())) return true;
    }
    return false;
}

// Nothing outside the cloth and the balls moves anything: what sleep needs of the World.
bool quiet(const World& w) { return w.settings.sleep.enabled && w.drivers.empty() && !windBlows(w.settings); }

float reachOf(const World& w) { return w.settings.collision.thickness + float(meanRestLength(w.cloth)); }

// Where each ball starts the frame (updateBallSleep measures its move from there).
void recordBallStarts(const World& w, SleepState& S) {
    S.ballFrameStart.resize(w.balls.size());
    for (size_t i = 0; i < w.balls.size(); ++i) S.ballFrameStart[i] = w.balls[i].x;
}

} // namespace

bool anyBallAwake(const std::vector<Ball>& balls) {
    return std::any_of(balls.begin(), balls.end(), [](const Ball& b) { return !b.asleep; });
}

int stillFramesToSleep(const Settings& s) {
    return std::clamp(int(std::ceil(s.sleep.delay / s.time.frameDt - 1e-6)), 1, 0xffff);
}

void wakeBallsIfTouched(World& w, StepState& state) {
    SleepState& S = state.sleep;
    recordBallStarts(w, S);
    if (std::any_of(w.balls.begin(), w.balls.end(), [](const Ball& b) { return b.asleep; })) {
        const bool touched = !quiet(w) || paramsChanged(w.settings, S.ballSettings);
        float fastest2 = 0.f;
        for (Index p = 0; p < w.cloth.particleCount(); ++p)
            if (w.cloth.invMass[p] > 0.f) fastest2 = std::max(fastest2, w.cloth.v[p].squaredNorm());
        const float reach = reachOf(w) + std::sqrt(fastest2) * w.settings.time.frameDt;
        for (Ball& b : w.balls) {
            if (!b.asleep) continue;
            if (touched || b.v != Vec3::Zero() || freeParticleWithin(w.cloth, b, reach))
                b.asleep = false, b.stillFrames = 0;
        }
    }
    S.ballSettings = w.settings;
}

void moveBallsBesideASleepingCloth(World& w, StepState& state) {
    if (!anyBallAwake(w.balls)) return;
    recordBallStarts(w, state.sleep);
    const Settings& s = w.settings;
    const int substeps = std::max({1, s.time.substeps, w.frameSubsteps});
    const float dt = s.time.frameDt / float(substeps);
    const Vec3 g(s.gravity.x, s.gravity.y, s.gravity.z);
    for (Ball& b : w.balls)
        if (!b.asleep)
            for (int k = 0; k < substeps; ++k) integrateBall(b, s.collision, g, dt);
    updateBallSleep(w, state);
}

void updateBallSleep(World& w, StepState& state) {
    const SleepState& S = state.sleep;
    const Settings& s = w.settings;
    const bool canSleep = quiet(w) && w.finite;
    const float step = s.sleep.speed * s.time.frameDt;
    const int need = stillFramesToSleep(s);
    for (size_t i = 0; i < w.balls.size(); ++i) {
        Ball& b = w.balls[i];
        if (b.asleep) continue;
        const bool still = canSleep && i < S.ballFrameStart.size() &&
                           (b.x - S.ballFrameStart[i]).squaredNorm() < step * step;
        b.stillFrames = still ? uint16_t(std::min<int>(b.stillFrames + 1, 0xffff)) : uint16_t(0);
        if (b.stillFrames >= need && !freeParticleWithin(w.cloth, b, reachOf(w))) {
            b.asleep = true;
            b.v = Vec3::Zero();
        }
    }
}

} // namespace clothtear
