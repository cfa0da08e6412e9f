// The stability guard's caps. With the linear material, a budget per particle (kParticleBudget:
// stability.cpp chooses the sub-step at which every particle is within it, springs.cpp scales the
// springs of any particle still past it). With the kes law also per-spring caps (springs.cpp
// applies them; stability.cpp chooses the sub-step at which the law needs none of them): a spring
// between particles of inverse mass w_a and w_b is capped where
//   k (w_a + w_b) dt^2 > kStiffnessCap   or   kd (w_a + w_b) dt > kDampingCap,
// which keeps a particle with ~8 springs inside the stable region of semi-implicit Euler.
#pragma once

namespace clothtear {

inline constexpr float kStiffnessCap = 1.f / 3.f;
inline constexpr float kDampingCap = 1.f / 6.f;

// The guard's budget per particle (Gershgorin, stability.cpp): dt^2 w_p sum(k) / 2 + dt w_p sum(kd)
// + dt c_air stays under this, 10 % inside the stable region. With the linear material the guard's
// step is the one at which every particle (but the lightest kGuardLightMass) is within it, and the
// springs of the others are scaled into it (springs.cpp, guardParticleBudget); the per-spring caps
// above are for the kes law and its hinges only.
inline constexpr float kParticleBudget = 0.9f;

} // namespace clothtear
