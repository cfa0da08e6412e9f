// tear.duration (limit.cpp): a spring tears once its strain has stayed over its threshold for the
// duration (at least a sub-step, at most a frame), not in the sub-step a spike lasts; under a moving
// hand at once. On the unit square, every particle pinned and its bottom edge at strain 0.5
// (test::stretchedPinnedSquare): the load lasts, and the sub-step in which it tears is known.
#include "clothtear/world.h"
#include "mesh_of.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace clothtear;

namespace {

struct EdgeRun {
    double firstTear = -1; // s, simulated: the time of the first tear event (-1: none)
    double dt = 0;         // s, the sub-step
    uint64_t deferred = 0; // the report's tears_deferred
};

// Steps one frame of `substeps` sub-steps with tear.duration = `durationSubsteps` sub-steps
// (less a hair: the duration rounds up to whole sub-steps); with `handMoves` a driver moves one
// pinned corner (away from the bottom edge, by a micrometre a frame).
EdgeRun stretchedEdge(float durationSubsteps, int substeps, bool handMoves = false) {
    World w;
    test::stretchedPinnedSquare(w, 0.5);
    w.settings.time.substeps = substeps;
    EdgeRun run;
    run.dt = double(w.settings.time.frameDt) / substeps;
    w.settings.tear.duration = float((durationSubsteps - 0.01) * run.dt);
    if (handMoves)
        for (Index p = 0; p < w.cloth.particleCount(); ++p)
            if (w.cloth.rest[p] == Vec3d(0, 1, 0)) w.drivers.push_back(Driver{{p}, Vec3(0.f, 6e-5f, 0.f)});
    w.step();
    if (!w.tearLog.events.empty()) run.firstTear = w.tearLog.events.front().time;
    run.deferred = w.profile.tearsDeferred;
    return run;
}

} // namespace

// With the duration at one sub-step the edge tears in the first; at four, in the fourth, and the
// three before it hold the spring (counted as deferred).
TEST(TearDuration, ALastingLoadTearsAfterTheDurationNotBefore) {
    const EdgeRun atOnce = stretchedEdge(1, 10);
    ASSERT_GE(atOnce.firstTear, 0.0) << "strain 0.5 tears";
    EXPECT_EQ(atOnce.deferred, 0u);
    const EdgeRun four = stretchedEdge(4, 10);
    ASSERT_GE(four.firstTear, 0.0);
    EXPECT_NEAR(four.firstTear - atOnce.firstTear, 3 * four.dt, 1e-3 * four.dt);
    EXPECT_EQ(four.deferred, 3u);
}

// A streak ends with its frame (a World restored from a checkpoint, taken between frames, tears as
// the one it came from), so the duration is at most a frame: at three sub-steps a frame, a duration
// of ten tears in the third.
TEST(TearDuration, IsAtMostAFrame) {
    const EdgeRun atOnce = stretchedEdge(1, 3);
    const EdgeRun ten = stretchedEdge(10, 3);
    ASSERT_GE(ten.firstTear, 0.0) << "a load that lasts the frame tears";
    EXPECT_NEAR(ten.firstTear - atOnce.firstTear, 2 * ten.dt, 1e-3 * ten.dt);
}

// Under a moving hand (a driver with a velocity) the hand's rips tear at once, as measured before the
// duration (bench/README.md, "A tear needs its load to last").
TEST(TearDuration, UnderAMovingHandTheLoadTearsAtOnce) {
    const EdgeRun atOnce = stretchedEdge(1, 10, true);
    const EdgeRun four = stretchedEdge(4, 10, true);
    ASSERT_GE(four.firstTear, 0.0);
    EXPECT_NEAR(four.firstTear, atOnce.firstTear, 1e-3 * four.dt);
    EXPECT_EQ(four.deferred, 0u);
}
