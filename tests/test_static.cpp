// Static accuracy: the direct static solve (Newton on the spring energy, static_solve.h) against a
// scalar equilibrium, the settled dynamics against the static solve, and the sag under mesh
// refinement. The 128 x 128 static solve takes seconds (sparse LDL^T of 49k unknowns), so the test
// compares 16, 32 and 64; clothbench --mode static adds 128 (bench/README.md).
//
// Section index:
//   [HELPERS]  curtain without limit, sag of the bottom centre
//   [SCALAR]   one free corner: Newton against bisection of the force balance
//   [SETTLED]  dynamics at rest against the static solve
//   [REFINE]   sag at 16, 32, 64
#include "clothtear/scenes.h"
#include "clothtear/static_solve.h"
#include "clothtear/world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace clothtear;

namespace {

// ========================================================================================== [HELPERS]

// The curtain as a pure spring network: no length limit and no stability guard (both change the
// equilibrium), no tearing, no ground.
World springCurtain(int resolution, std::vector<std::string> extra = {}) {
    World w;
    const std::string r = std::to_string(resolution);
    // Sleep off: a cloth slower than sleep.speed would be frozen before it is within 1e-4 of the sag.
    std::vector<std::string> o = {"cloth.resolution_x=" + r, "cloth.resolution_y=" + r,
                                  "limit.enabled=false",     "time.stability_guard=false",
                                  "tear.enabled=false",      "collision.ground=false",
                                  "sleep.enabled=false"};
    o.insert(o.end(), extra.begin(), extra.end());
    EXPECT_EQ(loadScene(w, "curtain", o), "");
    return w;
}


// =========================================================================================== [SCALAR]

// Triangle A = (-1, 0), B = (1, 0) pinned, C = (0, -h) hanging below. By symmetry C stays on the
// y axis at depth y; each of AC, BC has length l = sqrt(1 + y^2) and pulls with k (l - L) along
// itself, vertical share y / l:   2 k (l - L) y / l = m g,   k = S area / L^2, m = rho area / 3.
// The left side grows with y, so bisection finds the one root.
TEST(StaticSolve, OneFreeCornerMatchesTheScalarForceBalance) {
    World w;
    w.settings.material.bendStiffness = 0.f;
    MeshData m;
    const double h = 0.8;
    m.positions = {{-1, 0, 0}, {1, 0, 0}, {0, -h, 0}};
    m.triangles = {{0, 1, 2}}; // particles are numbered in order of first use: C is particle 2
    m.cornerUVs = {{Vec2d(0, 1), Vec2d(1, 1), Vec2d(0.5, 0)}};
    ASSERT_EQ(w.rebuild(m), "");
    w.cloth.setPinned(0, true);
    w.cloth.setPinned(1, true);
    const StaticSolveResult s = solveStatic(w.cloth, w.settings, w.cloth.x);
    ASSERT_TRUE(s.converged) << s.error << " residual " << s.residual;

    // The cloth stores rest length and weight as floats: take them from there, so the comparison
    // is about the solve, not about float rounding of the inputs (3e-8 here).
    const Spring* ac = nullptr;
    for (const Spring& sp : w.cloth.springs)
        if ((sp.a == 0 && sp.b == 2) || (sp.a == 2 && sp.b == 0))
            ac = &sp;
    ASSERT_NE(ac, nullptr);
    const double L = ac->rest;
    EXPECT_NEAR(L, std::sqrt(1 + h * h), 1e-6);
    const double k = double(w.settings.material.stretchStiffness) * ac->weight;
    EXPECT_NEAR(ac->weight, h / (L * L), 1e-6);
    const double mg = w.cloth.particleMass(2) * double(-w.settings.gravity.y);
    EXPECT_NEAR(w.cloth.particleMass(2), w.settings.material.density * h / 3, 1e-7);
    double lo = h, hi = 10;
    for (int i = 0; i < 200; ++i) {
        const double y = 0.5 * (lo + hi), l = std::sqrt(1 + y * y);
        (2 * k * (l - L) * y / l < mg ? lo : hi) = y;
    }
    EXPECT_NEAR(-s.x[2].y(), lo, 1e-9);
    EXPECT_GT(lo - h, 1e-3) << "the corner must visibly sag";
    EXPECT_NEAR(s.x[2].x(), 0.0, 1e-12);
}

// ========================================================================================== [SETTLED]

// A 24 x 24 curtain settled by the dynamics reaches the static solve's equilibrium. Air drag is
// raised to 2 kg/(m^2 s) (an e-folding time of 0.1 s; it does not change the equilibrium) so 3 s
// of simulation are enough; semi-implicit Euler at 10 sub-steps is inside its stable step here
// (h sqrt(rho / 3S) = 2.9 ms > 1.7 ms, see test_physics [RESOLUTION]), implicit Euler anywhere.
TEST(StaticSolve, SettledCurtainMatchesTheStaticSolve) {
    for (const char* integrator : {"semi-implicit-euler", "verlet", "implicit-euler"}) {
        World w = springCurtain(24, {std::string("time.integrator=") + integrator, "air.drag=2"});
        for (int f = 0; f < 3 * 60; ++f)
            w.step();
        ASSERT_TRUE(w.finite) << integrator;
        const StaticSolveResult s = solveStatic(w.cloth, w.settings, w.cloth.x);
        ASSERT_TRUE(s.converged) << s.error;
        double sum = 0, worst = 0;
        for (Index p = 0; p < w.cloth.particleCount(); ++p) {
            const double d = (w.cloth.x[p].cast<double>() - s.x[p]).norm();
            sum += d * d;
            worst = std::max(worst, d);
        }
        const double rms = std::sqrt(sum / double(w.cloth.particleCount()));
        const double sag = bottomCentreSag(w.cloth, w.settings.cloth, s.x);
        EXPECT_GT(sag, 0.03) << "the springs must carry a visible load";
        // Float state: round-off is about 1e-7 m; what is left of the motion after 3 s is smaller.
        EXPECT_LT(rms, 1e-4 * sag) << integrator;
        EXPECT_LT(worst, 1e-3 * sag) << integrator;
        RecordProperty(std::string("settled_rms_m_") + integrator, std::to_string(rms));
    }
}

// =========================================================================================== [REFINE]

// Resolution independence of the spring network (weights area / rest^2, lumped masses): the static
// sag of the same 2 m curtain at 16, 32 and 64 particles per side agrees within 5% (measured: 0.2%).
TEST(StaticSolve, SagConvergesUnderMeshRefinement) {
    std::vector<double> sag;
    for (int res : {16, 32, 64}) {
        World w = springCurtain(res);
        const StaticSolveResult s = solveStatic(w.cloth, w.settings, w.cloth.x);
        ASSERT_TRUE(s.converged) << res << ": " << s.error << " residual " << s.residual;
        sag.push_back(bottomCentreSag(w.cloth, w.settings.cloth, s.x));
        RecordProperty("static_sag_" + std::to_string(res), std::to_string(sag.back()));
    }
    EXPECT_GT(sag[0], 0.03);
    EXPECT_NEAR(sag[1], sag[2], 0.05 * sag[2]);
    EXPECT_NEAR(sag[0], sag[2], 0.05 * sag[2]);
    // Refinement converges: the 32-64 difference is smaller than the 16-32 one.
    EXPECT_LT(std::abs(sag[1] - sag[2]), std::abs(sag[0] - sag[1]));
}

} // namespace
