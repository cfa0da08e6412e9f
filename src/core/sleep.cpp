// Sleep: a cloth at rest is not simulated until something can move it (world.h, sleep.*).
//
// Falling asleep: after a frame in which every particle moved slower than sleep.speed, continuously
// for sleep.delay seconds, with nothing that moves it by itself (no drivers, no wind). Waking: a
// ball whose reach over the next frame (radius, thickness, the distance it travels) overlaps the
// box the cloth had when it fell asleep; a driver; wind; any change of a parameter, of the topology
// or of the pinned particles; World::wake() (impulses and the app's tools call it). Asleep, a frame only
// advances the clock: the state stays exactly as it was, so waking continues from there.
#include "clothtear/params.h"
#include "clothtear/world.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace clothtear {
namespace {

// Which particles are pinned (a tool may pin or release one while the cloth sleeps).
uint64_t pinHash(const Cloth& c) {
    uint64_t h = c.particleCount();
    for (Index p = 0; p < c.particleCount(); ++p)
        if (c.flags[p] & kPinned)
            h = (h ^ p) * 0x100000001b3ull;
    return h;
}

uint64_t settingsHash(const Settings& s) {
    uint64_t h = 0xcbf29ce484222325ull;
    for (const ParamInfo& p : allParams()) {
        const double v = getParam(s, p);
        uint64_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        h = (h ^ bits) * 0x100000001b3ull;
    }
    return h;
}

} // namespace

void World::wake() {
    asleep = false;
    restSince_ = -1;
}

bool World::stayAsleep() {
    if (!asleep)
        return false;
    const bool windBlows =
        settings.wind.enabled && settings.wind.speed > 0.f && settings.wind.dragCoefficient > 0.f;
    bool touched = !settings.sleep.enabled || !drivers.empty() || windBlows ||
                   cloth.topologyRevision != sleepTopology_ || settingsHash(settings) != sleepSettingsHash_ ||
                   pinHash(cloth) != sleepPins_;
    const Vec3 g(settings.gravity.x, settings.gravity.y, settings.gravity.z);
    for (const Ball& b : balls) {
        // Where the ball can be by the end of the frame (gravity included), grown by its radius.
        const float T = settings.time.frameDt;
        const float reach =
            b.radius + settings.collision.thickness + b.v.norm() * T + 0.5f * g.norm() * T * T;
        touched |= !((b.x.array() + reach < sleepLo_.array()).any() ||
                     (b.x.array() - reach > sleepHi_.array()).any());
    }
    if (touched)
        wake();
    return asleep;
}

// Rest is judged by how far the particles moved over the frame, not by their velocities: where the
// length limit holds a particle against gravity, its velocity can keep a value that never moves it
// (measured: 0.094 m/s upward on a particle next to a pinned corner of the 64x64 curtain, at rest).
float World::frameSpeed() const {
    const std::vector<Vec3>& x0 = scratch_.frameStart;
    const size_t n = std::min(x0.size(), cloth.particleCount());
    float worst = 0.f;
    for (size_t p = 0; p < n; ++p)
        worst = std::max(worst, (cloth.x[p] - x0[p]).squaredNorm());
    return n ? std::sqrt(worst) / settings.time.frameDt : std::numeric_limits<float>::infinity();
}

void World::updateSleep() {
    const bool windBlows =
        settings.wind.enabled && settings.wind.speed > 0.f && settings.wind.dragCoefficient > 0.f;
    if (!settings.sleep.enabled || !finite || !drivers.empty() || windBlows ||
        !(frameSpeed() < settings.sleep.speed)) {
        restSince_ = -1;
        return;
    }
    if (restSince_ < 0)
        restSince_ = time;
    if (time - restSince_ + 1e-9 < settings.sleep.delay)
        return;
    sleepLo_ = Vec3::Constant(1e30f);
    sleepHi_ = Vec3::Constant(-1e30f);
    for (const Vec3& x : cloth.x)
        sleepLo_ = sleepLo_.cwiseMin(x), sleepHi_ = sleepHi_.cwiseMax(x);
    sleepSettingsHash_ = settingsHash(settings);
    sleepTopology_ = cloth.topologyRevision;
    sleepPins_ = pinHash(cloth);
    asleep = true;
    // A ball already overlapping the cloth's box keeps it awake: it may be resting on it.
    stayAsleep();
}

} // namespace clothtear
