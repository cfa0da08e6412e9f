// Extended position-based dynamics with small steps: Macklin, Mueller, Chentanez, "XPBD:
// position-based simulation of compliant constrained dynamics", MIG 2016, and Macklin, Storey, Lu,
// Terdiman, Chentanez, Jeschke, Mueller, "Small steps in physics simulation", SCA 2019: one
// constraint iteration per sub-step, many sub-steps (here: the world's sub-steps).
//
// Each spring is a distance constraint C = |x_b - x_a| - L with compliance alpha = 1 / k, which
// has the spring's energy k C^2 / 2, and damping beta = kd. With one iteration per sub-step the
// multiplier starts at 0, and XPBD's update (Macklin 2016, Eq. 18 and 26, alpha~ = alpha / dt^2,
// gamma = alpha~ beta dt) multiplied through by k dt^2 reads
//
//   dlambda = (-k dt^2 C - kd dt grad C . (x - x_n)) / ((k dt^2 + kd dt)(w_a + w_b) + 1)
//   x_a -= w_a dlambda n,   x_b += w_b dlambda n,   n = (x_b - x_a) / |x_b - x_a|
//
// which stays defined for k = 0 (a pure damper) and tends to a hard constraint as k grows.
// Order of one sub-step: v += dt a_ext; dx = dt v; springs in array order (Gauss-Seidel, serial,
// deterministic) on dx; v = dx / dt; x += dx. The step works on the displacement dx = x - x_n, not
// on x: v = (x - x_n) / dt from rounded float positions is quantized to ulp(x) / dt, which at small
// sub-steps is larger than the error being measured.
#pragma once
#include "reference_step.h"

#include <vector>

namespace clothtear {

// One sub-step. `dx` is scratch (resized here).
void xpbdStep(Cloth& cloth, const ReferenceStepInput& in, std::vector<Vec3>& dx);

} // namespace clothtear
