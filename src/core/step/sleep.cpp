// Sleep: a cloth at rest is not simulated until something can move it (world.h, sleep.*).
//
// Falling asleep: after a frame in which every particle moved slower than sleep.speed, continuously
// for sleep.delay seconds, with nothing that moves it by itself (no drivers, no wind). Waking: a
// ball whose reach over the next frame (radius, thickness, the distance it travels) overlaps the
// box the cloth had when it fell asleep (a sleeping ball cannot: ball_sleep.cpp); a driver; wind;
// any change of a parameter, of the topology or of the pinned particles; World::wake() (impulses
// and the app's tools call it). Asleep, a frame advances the clock and moves only the awake balls,
// none of which can reach the cloth that frame (they fly and bounce on the ground): the cloth stays
// exactly as it was, so waking continues from there.
#include "sleep.h"

#include "clothtear/params.h"
#include "step_context.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace clothtear {

bool aBallCanReach(const World& w, const Vec3& lo, const Vec3& hi) {
    const Settings& settings = w.settings;
    const Vec3 g(settings.gravity.x, settings.gravity.y, settings.gravity.z);
    const float T = settings.time.frameDt;
    for (const Ball& b : w.balls) {
        if (b.asleep) continue; // nothing within its reach moves (ball_sleep.cpp)
        // Where the ball can be by the end of the frame (gravity included), grown by its radius.
        const float reach = b.radius + settings.collision.thickness + b.v.norm() * T + 0.5f * g.norm() * T * T;
        if (!((b.x.array() + reach < lo.array()).any() || (b.x.array() - reach > hi.array()).any())) return true;
    }
    return false;
}

bool paramsChanged(const Settings& now, const Settings& then) {
    for (const ParamInfo& p : allParams())
        if (getParam(now, p) != getParam(then, p)) return true;
    return false;
}

void World::wake() {
    asleep = false;
    state_->sleep.restSince = -1;
    wakePieces(*this, *state_);
    for (Ball& b : balls) b.asleep = false, b.stillFrames = 0;
}

bool stayAsleep(World& w, StepState& state) {
    if (!w.asleep)
        return false;
    const Settings& settings = w.settings;
    const SleepState& S = state.sleep;
    // A pin set or released changes the cloth's mass revision (Cloth::setPinned).
    const bool touched = !settings.sleep.enabled || !w.drivers.empty() || windBlows(settings) ||
                         w.cloth.topologyRevision != S.topology || w.cloth.massRevision != S.mass ||
                         paramsChanged(settings, S.settings) || aBallCanReach(w, S.lo, S.hi);
    if (touched)
        w.wake();
    return w.asleep;
}

// Rest is judged by how far the particles moved over the frame, not by their velocities: where the
// length limit holds a particle against gravity, its velocity can keep a value that never moves it
// (measured: 0.094 m/s upward on a particle next to a pinned corner of the 64x64 curtain, at rest).
static float frameSpeed(const World& w, const StepState& state) {
    const Cloth& cloth = w.cloth;
    const std::vector<Vec3>& x0 = state.sleep.frameStart;
    const size_t n = std::min(x0.size(), cloth.particleCount());
    float worst = 0.f;
    for (size_t p = 0; p < n; ++p)
        worst = std::max(worst, (cloth.x[p] - x0[p]).squaredNorm());
    return n ? std::sqrt(worst) / w.settings.time.frameDt : std::numeric_limits<float>::infinity();
}

void updateSleep(World& w, StepState& state) {
    const Settings& settings = w.settings;
    SleepState& S = state.sleep;
    if (!settings.sleep.enabled || !w.finite || !w.drivers.empty() || windBlows(settings) ||
        !(frameSpeed(w, state) < settings.sleep.speed)) {
        S.restSince = -1;
        return;
    }
    if (S.restSince < 0)
        S.restSince = w.time;
    if (w.time - S.restSince + 1e-9 < settings.sleep.delay)
        return;
    S.lo = Vec3::Constant(1e30f);
    S.hi = Vec3::Constant(-1e30f);
    for (const Vec3& x : w.cloth.x)
        S.lo = S.lo.cwiseMin(x), S.hi = S.hi.cwiseMax(x);
    S.settings = settings;
    S.topology = w.cloth.topologyRevision;
    S.mass = w.cloth.massRevision;
    w.asleep = true;
    // A ball already overlapping the cloth's box keeps it awake: it may be resting on it.
    stayAsleep(w, state);
}

} // namespace clothtear
