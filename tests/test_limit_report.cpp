// StepProfile::limitCapped / limitCappedSprings: sub-steps whose length limit ran out of passes while
// still correcting springs (the JSON report's limit_capped_*, the app's stats pane).
#include "clothtear/scenes.h"
#include "clothtear/world.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace clothtear;

namespace {
World curtain(std::vector<std::string> sets) {
    World w;
    sets.push_back("sleep.enabled=false");
    EXPECT_EQ(loadScene(w, "curtain", sets), "");
    return w;
}
} // namespace

TEST(LimitReport, SettledCurtainNeverRunsOutOfPasses) {
    World w = curtain({});
    for (int f = 0; f < 120; ++f) w.step(); // the first ~0.6 s the falling cloth does run out
    const StepProfile before = w.profile;
    for (int f = 0; f < 60; ++f) w.step();
    EXPECT_EQ(w.profile.limitCapped, before.limitCapped);
    EXPECT_EQ(w.profile.limitCappedSprings, before.limitCappedSprings);
    EXPECT_EQ(w.profile.substeps - before.substeps, 60u * uint64_t(w.frameSubsteps));
}

TEST(LimitReport, OnePassUnderWindRunsOutAndCountsTheSprings) {
    // One Jacobi pass cannot hold a 32 x 32 cloth in a 6 m/s wind: many sub-steps end with springs
    // still being corrected (134 of the 300 when written, as the wind builds up); each counts a
    // spring. (Gauss-Seidel takes at least 4 x the cloth's depth in passes: limit.cpp, passCap.)
    World w = curtain({"cloth.resolution_x=32", "cloth.resolution_y=32", "wind.enabled=true", "wind.speed=6",
                       "tear.enabled=false", "limit.solver=jacobi", "limit.iterations=1"});
    for (int f = 0; f < 30; ++f) w.step();
    EXPECT_GT(w.profile.limitCapped, w.profile.substeps / 4);
    EXPECT_GE(w.profile.limitCappedSprings, w.profile.limitCapped);
    // The same with plenty of passes: fewer capped sub-steps (the counter follows the cause).
    World many = curtain({"cloth.resolution_x=32", "cloth.resolution_y=32", "wind.enabled=true", "wind.speed=6",
                          "tear.enabled=false", "limit.solver=jacobi", "limit.iterations=50"});
    for (int f = 0; f < 30; ++f) many.step();
    EXPECT_LT(many.profile.limitCapped, w.profile.limitCapped) << many.profile.limitCapped;
}
