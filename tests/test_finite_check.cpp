// Non-finite values are caught at the phase boundary where they appear and reported with the phase
// and the particle (world.finite / nonFiniteWhere, the runner's non_finite_where), never silently.
#include "clothtear/params.h"
#include "clothtear/scenes.h"

#include <gtest/gtest.h>

#include <limits>

using namespace clothtear;

namespace {

World checkedCurtain() {
    World w;
    EXPECT_EQ(loadScene(w, "curtain",
                        std::vector<std::string>{"cloth.resolution_x=12", "cloth.resolution_y=12",
                                                 "check.finite=1"}),
              "");
    return w;
}

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

} // namespace

TEST(FiniteCheck, ValueSetFromOutsideTheStepIsReportedBeforeTheSubStep) {
    World w = checkedCurtain();
    w.step();
    ASSERT_TRUE(w.finite);
    w.cloth.v[100].y() = kNaN;
    w.step();
    EXPECT_FALSE(w.finite);
    EXPECT_TRUE(contains(w.nonFiniteWhere, "before a sub-step")) << w.nonFiniteWhere;
    EXPECT_TRUE(contains(w.nonFiniteWhere, "at frame 1")) << w.nonFiniteWhere;
    EXPECT_TRUE(contains(w.nonFiniteWhere, "particle 100: velocity")) << w.nonFiniteWhere;
}

TEST(FiniteCheck, NaNGravityIsTracedToTheIntegratorAndTheFirstFreeParticle) {
    World w = checkedCurtain();
    setParamUnchecked(w.settings, *findParam("gravity.y"), std::nan(""));
    w.step();
    EXPECT_FALSE(w.finite);
    Index firstFree = 0;
    while (w.cloth.pinned(firstFree))
        ++firstFree; // pinned particles are not integrated
    // x += v dt makes the position NaN too; positions are reported first.
    EXPECT_TRUE(contains(w.nonFiniteWhere, "after phase 'integrate' at frame 0")) << w.nonFiniteWhere;
    EXPECT_TRUE(contains(w.nonFiniteWhere, "particle " + std::to_string(firstFree) + ": position"))
        << w.nonFiniteWhere;
}

TEST(FiniteCheck, NaNSpringIsTracedToTheSpringPhaseAndItsForce) {
    World w = checkedCurtain();
    const Index s = Index(w.cloth.springs.size() / 2);
    w.cloth.springs[s].rest = kNaN;
    const Index first = std::min(w.cloth.springs[s].a, w.cloth.springs[s].b);
    w.step();
    EXPECT_FALSE(w.finite);
    EXPECT_TRUE(contains(w.nonFiniteWhere, "after phase 'springs'")) << w.nonFiniteWhere;
    EXPECT_TRUE(contains(w.nonFiniteWhere, "particle " + std::to_string(first) + ": force"))
        << w.nonFiniteWhere;
}

TEST(FiniteCheck, BallIsChecked) {
    World w = checkedCurtain();
    Ball b;
    b.x = Vec3(0.f, 0.f, 1.f);
    b.v = Vec3(0.f, 0.f, kNaN);
    w.balls.push_back(b);
    w.step();
    EXPECT_FALSE(w.finite);
    EXPECT_TRUE(contains(w.nonFiniteWhere, "ball 0: velocity")) << w.nonFiniteWhere;
}

// An unstable set-up on purpose (no stability guard, no limit, stiff springs) blows up; the report
// names a phase and a particle that really is non-finite, and nothing is reported before.
TEST(FiniteCheck, RunawayIsReportedWithAPhaseAndANonFiniteParticle) {
    World w;
    ASSERT_EQ(
        loadScene(w, "curtain",
                  std::vector<std::string>{"cloth.resolution_x=12", "cloth.resolution_y=12", "check.finite=1",
                                           "time.stability_guard=0", "limit.enabled=0", "tear.enabled=0",
                                           "material.stretch_stiffness=3000"}),
        "");
    int frames = 0;
    while (w.finite && frames < 600) {
        w.step();
        ++frames;
    }
    ASSERT_FALSE(w.finite) << "the set-up was meant to explode";
    bool namesPhase = false;
    for (int p = 0; p < int(Phase::Count); ++p)
        namesPhase |= contains(w.nonFiniteWhere, std::string("after phase '") + phaseName(Phase(p)) + "'");
    EXPECT_TRUE(namesPhase) << w.nonFiniteWhere;
    const size_t at = w.nonFiniteWhere.find(": particle ");
    ASSERT_NE(at, std::string::npos) << w.nonFiniteWhere;
    const Index p = Index(std::stoul(w.nonFiniteWhere.substr(at + 11)));
    ASSERT_LT(p, w.cloth.particleCount());
    // A named position or velocity is non-finite; a named force (possibly on a pinned particle,
    // which the integrator never moves) has made some particle non-finite by the frame's end.
    if (!contains(w.nonFiniteWhere, ": force")) {
        EXPECT_FALSE(w.cloth.x[p].allFinite() && w.cloth.v[p].allFinite()) << w.nonFiniteWhere;
    }
    bool anyNonFinite = false;
    for (Index q = 0; q < w.cloth.particleCount(); ++q)
        anyNonFinite |= !w.cloth.x[q].allFinite() || !w.cloth.v[q].allFinite();
    EXPECT_TRUE(anyNonFinite);
}

#if !CLOTHTEAR_CHECK_FINITE
// Without check.finite (and outside Debug) the frame's end still catches it: never silent.
TEST(FiniteCheck, WithoutTheCheckTheFrameEndStillReportsIt) {
    World w;
    ASSERT_EQ(
        loadScene(w, "curtain", std::vector<std::string>{"cloth.resolution_x=12", "cloth.resolution_y=12"}),
        "");
    w.cloth.v[100].x() = kNaN;
    w.step();
    EXPECT_FALSE(w.finite);
    EXPECT_FALSE(w.nonFiniteWhere.empty());
    EXPECT_FALSE(contains(w.nonFiniteWhere, "after phase")) << w.nonFiniteWhere;
}
#endif
