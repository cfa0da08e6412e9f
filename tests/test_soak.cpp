// The soak (src/cli/soak.h) and what it found: each finding is a test here, with the numbers it had.
#include "soak.h"
#include "clothtear/params.h"
#include "clothtear/scenes.h"

#include <gtest/gtest.h>

#include <sstream>

using namespace clothtear;

// A short soak at a small resolution: the tool runs, interacts, checks and reports every line.
TEST(Soak, ShortRunInteractsAndEveryCheckHolds) {
    SoakOptions o;
    o.resolution = 24;
    o.maxFrames = 240;
    o.reportSeconds = 1e6; // first and last line only
    std::ostringstream log;
    const SoakResult r = runSoak(o, log);
    EXPECT_TRUE(r.ok()) << r.failure << "\n" << log.str();
    EXPECT_EQ(r.frames, 240);
    EXPECT_GT(r.grabs + r.impulses + r.balls, 0u);
    EXPECT_GT(r.rssEndMiB, 0.0);
    EXPECT_NE(log.str().find("finite yes  valid yes"), std::string::npos) << log.str();
}

// Soak finding 1: a particle let go by a tool (unpinned) must get the stability guard's cap from its
// first sub-step. The spring cache was keyed on the pins seen by the last integration, so for one
// sub-step a released particle kept the uncapped stiffness of a spring between two pinned ends; a
// torn-off sliver of 1e-15 kg reached 1e8 m/s.
TEST(SoakFindings, ReleasedParticleIsCappedFromItsFirstSubStep) {
    World w;
    ASSERT_EQ(
        loadScene(w, "curtain",
                  std::vector<std::string>{"cloth.resolution_x=10", "cloth.resolution_y=10", "gravity.y=0",
                                           "material.stretch_stiffness=1e5", "limit.enabled=0",
                                           "tear.enabled=0", "collision.ground=0", "check.finite=1"}),
        "");
    for (Index p = 0; p < w.cloth.particleCount(); ++p)
        w.cloth.setPinned(p, true);
    // Two sub-steps: the spring cache now holds every spring with both ends pinned (nothing to cap),
    // keyed on the pins the integration of the first one saw.
    w.substep();
    w.substep();
    const Index p = 45;
    w.cloth.x[p].x() += 0.02f; // 2 cm along the springs of its row
    w.cloth.setPinned(p, false);
    w.substep();
    const float dt = w.settings.time.frameDt / float(w.settings.time.substeps);
    // Capped springs (k w dt^2 <= 1/3 each, 8 of them at most) move it back by at most a few times
    // its offset per sub-step; uncapped, 1e5 N/m on 10 grams is hundreds of m/s.
    EXPECT_LT(w.cloth.v[p].norm(), 3.f * 0.02f / dt) << "velocity " << w.cloth.v[p].transpose();
    EXPECT_TRUE(w.finite) << w.nonFiniteWhere;
}

// Soak finding 2: wind on a sliver. The corners' masses come from the rest area; a sliver left by
// repeated tears (rest area 1e-15 m^2) cannot be that thin in float positions, so its current area,
// and the wind it caught, was 10^4 and more times its mass share: it exploded in one sub-step.
TEST(SoakFindings, WindOnASliverIsBoundedByItsRestArea) {
    MeshData m;
    m.positions = {Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(0.5, 1e-6, 0)}; // rest area 5e-7 m^2
    m.triangles = {{0, 1, 2}};
    m.cornerUVs = {{Vec2d(0, 0), Vec2d(1, 0), Vec2d(0.5, 1)}};
    World w;
    for (const char* set : {"gravity.y=0", "material.stretch_stiffness=0", "material.stretch_damping=0",
                            "material.bend_stiffness=0", "material.bend_damping=0", "limit.enabled=0",
                            "tear.enabled=0", "collision.ground=0", "wind.enabled=1", "wind.speed=6",
                            "wind.gust=0", "air.drag=0", "cloth.pin=none", "check.finite=1"})
        ASSERT_EQ(applyAssignment(w.settings, set), "") << set;
    ASSERT_EQ(w.rebuild(m), "");
    w.cloth.x[2] = Vec3(0.5f, 1.f, 0.f); // live shape: current area 0.5 m^2, a million times the rest area
    w.substep();
    const float dt = w.settings.time.frameDt / float(w.settings.time.substeps);
    // At most twice the rest area catches wind: F <= c (2 A_rest) v^2 / 3 per corner, m = rho A_rest / 3.
    const float bound = 1.f * 2.f * 36.f / 0.2f * dt;
    for (Index p = 0; p < 3; ++p)
        EXPECT_LE(w.cloth.v[p].norm(), bound * 1.01f) << "corner " << p << ": " << w.cloth.v[p].transpose();
    EXPECT_GT(w.cloth.v[0].norm(), 0.f) << "the wind still blows on it";
}
