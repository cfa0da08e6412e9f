// The stability guard's per-spring caps (springs.cpp applies them; stability.cpp chooses the
// sub-step at which the material needs none of them). A spring between particles of inverse mass
// w_a and w_b is capped where
//   k (w_a + w_b) dt^2 > kStiffnessCap   or   kd (w_a + w_b) dt > kDampingCap,
// which keeps a particle with ~8 springs inside the stable region of semi-implicit Euler.
#pragma once

namespace clothtear {

inline constexpr float kStiffnessCap = 1.f / 3.f;
inline constexpr float kDampingCap = 1.f / 6.f;

} // namespace clothtear
