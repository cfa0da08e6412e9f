// Settings for tests that watch one force alone (shared by the physics, limit, stability and wind
// tests): every force but the springs switched off; and the one-particle oscillator of the
// stability and kes tests.
#pragma once
#include "clothtear/settings.h"
#include "clothtear/world.h"

#include <string>

namespace clothtear::test {

// No gravity, no air, no spring damping, no limiting, no tearing, no ground, no wind, nothing
// pinned. A test switches on what it watches.
inline Settings quietSettings() {
    Settings s;
    s.gravity = GravitySettings{0.f, 0.f, 0.f};
    s.air.dragCoefficient = 0.f;
    s.material.stretchDamping = 0.f;
    s.material.bendDamping = 0.f;
    s.limit.enabled = false;
    s.tear.enabled = false;
    s.collision.ground = false;
    s.wind.enabled = false;
    s.cloth.pin = PinMode::None;
    return s;
}

// One oscillator: the world's cloth becomes one triangle with A = (-1, 0) and B = (1, 0) pinned and
// C = (0, 1) free, C displaced by 1 mm across A-B (w.settings as the test set them). C then swings
// on the springs AC and BC at omega^2 = k / m_C (k per spring; GuardKeepsTheMaterialWithinItsBudgetAndCapsEachSpringWhileABallIsNear).
// Returns rebuild's error ("" when built).
inline std::string buildOscillator(World& w) {
    MeshData m;
    m.positions = {{-1, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.triangles = {{0, 1, 2}};
    m.cornerUVs = {{Vec2d(0, 0), Vec2d(1, 0), Vec2d(0.5, 1)}};
    const std::string error = w.rebuild(m);
    if (!error.empty()) return error;
    w.cloth.setPinned(0, true);
    w.cloth.setPinned(1, true);
    w.cloth.x[2].y() += 1e-3f;
    return "";
}

} // namespace clothtear::test
