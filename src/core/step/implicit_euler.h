// Implicit (backward) Euler with one linearized Newton step per sub-step, Baraff & Witkin,
// "Large steps in cloth simulation", SIGGRAPH 1998, sections 3-5:
//
//   (M - dt D - dt^2 K) dv = dt (f + dt K v),   v += dv,   x += dt v
//
// with f the spring, damping, gravity, air and wind forces at the start of the step, K = df/dx and
// D = df/dv their Jacobians. Solved by Eigen's conjugate gradient (Jacobi preconditioner) in
// double precision. Pinned particles are filtered out (their dv is 0, so their rows and columns
// drop out of the system; a driven pinned particle still enters f and K v with its velocity).
//
// Per spring (ends a, b; d = x_b - x_a, l = |d|, n = d / l, rest L, k, kd):
//   f_a = (k (l - L) + kd (v_b - v_a).n) n = -f_b
//   df_a/dx_a = -k (n n^T + max(0, 1 - L / l) (I - n n^T))      (the geometric term is dropped for a
//                                                                 compressed spring, Choi & Ko 2002,
//                                                                 so the matrix stays positive definite)
//   df_a/dv_a = -kd n n^T     (the damping force's dependence on x is neglected, as in Baraff-Witkin)
// and the (a, b) blocks are the negatives. Air drag f = -c A v adds c A I = m dragPerMass I to M's
// diagonal (times dt).
//
// material.model = kes (Tagawa's law, kes.h): a structural spring's force is F(l) = T(e) w
// (e = (l - L) / L, w = weight L the spring's width), so
//   df_a/dx_a = -(T'(e) weight n n^T + max(0, F / l) (I - n n^T))
// (the linear spring's matrix is this with T = k (l - L) / weight / L). A hinge (c, d across
// edge a-e) with angle theta and torque tau = M(K) w gives f_i = -tau dtheta/dx_i, and, without the
// term tau d^2 theta / dx_i dx_j (Gauss-Newton, so the matrix stays positive definite),
//   df_i/dx_j = -S w / L  dtheta/dx_i dtheta/dx_j^T
// with S the law's largest slope dM/dK, D + alpha D1, which a reversal within the step jumps to
// (HingeTangent in kes.h: with the slope of the branch the hinge was on, large steps zig-zagged
// and lost the hysteresis). The hinges'
// blocks (c, d) are the bend-shear spring's; the pattern holds them (the step passes the
// bend-shear springs with zero stiffness).
#pragma once
#include "reference_step.h"

#include <Eigen/Sparse>
#include <memory>
#include <vector>

namespace clothtear {

// Sparsity pattern and work arrays, built on the first step with this cache. The step starts a
// fresh cache when the topology or the pinned set changes (step_state.h, ImplicitCacheSlot).
struct ImplicitEulerCache {
    bool built = false;
    std::vector<int> row; // per particle: first unknown (3 per free particle), -1 if pinned
    Eigen::SparseMatrix<double, Eigen::RowMajor>
        A; // 3 nf x 3 nf (nf free particles), symmetric, full storage
    // Per spring (both kinds in order): offsets into A.valuePtr() of the first entry of each of the
    // three columns of the blocks (a, a), (a, b), (b, a), (b, b); -1 where an end is pinned.
    std::vector<std::array<int, 12>> springSlots;
    std::vector<std::array<int, 3>> diagSlots; // per particle: its diagonal block's columns
    Eigen::VectorXd b;
    Eigen::VectorXd dv; // the last solve: the next solve's first guess (a world file saves it)
    std::vector<Eigen::Vector3d> force; // N per particle at the start of the step
    int lastIterations = 0;             // CG iterations of the last solve
    double lastError = 0;               // CG relative residual of the last solve
};

struct ImplicitEulerOptions {
    double tolerance = 1e-5; // relative residual
    int maxIterations = 200;
};

// One sub-step: x, v of every free particle.
void implicitEulerStep(Cloth& cloth, const ReferenceStepInput& in, const ImplicitEulerOptions& options,
                       ImplicitEulerCache& cache);

} // namespace clothtear
