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

#include <algorithm>
#include <cmath>
#include <limits>
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

// Sag of a grid cloth at the bottom-centre particle(s) (two when the resolution is even): how far the
// positions `x` (float dynamics or double static solve) hang below the rest positions there, m;
// NaN when no particle is there. The measure of the static and refinement checks (clothbench
// `static`, tests/test_static.cpp, tests/test_physics.cpp).
template <class V>
double bottomCentreSag(const Cloth& cloth, const ClothSettings& grid, const std::vector<V>& x) {
    double bottom = std::numeric_limits<double>::infinity();
    for (const Vec3d& r : cloth.rest) bottom = std::min(bottom, r.y());
    const double spacing = double(grid.width) / (grid.resolutionX - 1);
    double sum = 0, restSum = 0;
    int count = 0;
    for (Index p = 0; p < cloth.particleCount(); ++p) {
        const Vec3d& r = cloth.rest[p];
        if (r.y() > bottom + 1e-9 || std::abs(r.x()) > 0.5 * spacing + 1e-9) continue;
        sum += double(x[p].y());
        restSum += r.y();
        ++count;
    }
    return count ? (restSum - sum) / count : std::numeric_limits<double>::quiet_NaN();
}

} // namespace clothtear
