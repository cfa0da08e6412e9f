// Settings for tests that watch one force alone (shared by the physics, limit, stability and wind
// tests): every force but the springs switched off.
#pragma once
#include "clothtear/settings.h"

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

} // namespace clothtear::test
