// A direct static solve of a cloth's spring network: the equilibrium under gravity with the pinned
// particles held where they are, by Newton's method on the total potential energy (Eigen's sparse
// LDL^T), for the accuracy checks of bench/clothbench and tests/test_static.cpp.
//
//   E(x) = sum_springs k/2 (|x_b - x_a| - L)^2 - sum_p m_p g . x_p,   k = stiffness * weight
//
// (structural and bend-shear springs, as in the dynamics). The length limit, collisions and
// tearing are not part of this model: it is the equilibrium the dynamics reach with limit.enabled
// off and no stability guard.
#pragma once
#include "clothtear/cloth.h"
#include "clothtear/settings.h"

#include <span>
#include <string>
#include <vector>

namespace clothtear {

struct StaticSolveOptions {
    int maxIterations = 100; // Newton iterations
    double tolerance = 1e-9; // stop when |grad E| (free particles) <= tolerance * total weight (N)
};

struct StaticSolveResult {
    std::vector<Vec3d> x; // m, equilibrium positions (pinned particles unchanged)
    int iterations = 0;
    double residual = 0; // |grad E| / total weight at the end
    bool converged = false;
    std::string error; // "" or why it failed (factorization)
};

// Starts from `start` (usually cloth.x). Uses material stiffnesses and gravity from `settings`.
StaticSolveResult solveStatic(const Cloth& cloth, const Settings& settings, std::span<const Vec3> start,
                              const StaticSolveOptions& options = {});

} // namespace clothtear
