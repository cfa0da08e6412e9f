// Sleep (src/core/sleep.cpp) and the ball broad phase (src/core/collide.cpp, trianglesIn): what
// they skip must not change what is simulated.
#include "clothtear/scenes.h"
#include "clothtear/world.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace clothtear;

namespace {

World settled(std::vector<std::string> extra = {}) {
    World w;
    std::vector<std::string> o = {"cloth.resolution_x=12", "cloth.resolution_y=12", "air.drag=2"};
    o.insert(o.end(), extra.begin(), extra.end());
    EXPECT_EQ(loadScene(w, "curtain", o), "");
    for (int f = 0; f < 6 * 60 && !w.asleep; ++f)
        w.step();
    return w;
}

// A curtain at rest falls asleep; asleep, frames leave the state exactly as it was; each way of
// touching it wakes it: a ball coming near, unpinning a particle, an impulse, a changed parameter.
TEST(Sleep, RestingCurtainSleepsAndWakesWhenTouched) {
    World w = settled();
    ASSERT_TRUE(w.asleep) << "max speed " << w.maxSpeed << " m/s";
    const std::vector<Vec3> x = w.cloth.x;
    const uint64_t substeps = w.profile.substeps;
    for (int f = 0; f < 30; ++f)
        w.step();
    EXPECT_TRUE(w.asleep);
    EXPECT_EQ(w.cloth.x, x);
    EXPECT_EQ(w.profile.substeps, substeps) << "asleep, nothing is simulated";
    EXPECT_EQ(w.sleptFrames, 30u);

    // A ball far away does not wake it; one flying at it does, before it arrives.
    Ball far;
    far.x = Vec3(0.f, 0.f, 10.f);
    w.balls.push_back(far);
    w.step();
    EXPECT_TRUE(w.asleep);
    w.balls[0].v = Vec3(0.f, 0.f, -600.f); // reaches the cloth within this frame
    w.step();
    EXPECT_FALSE(w.asleep);
    EXPECT_GT(w.profile.substeps, substeps);

    World u = settled();
    ASSERT_TRUE(u.asleep);
    for (Index p = 0; p < u.cloth.particleCount(); ++p)
        if (u.cloth.pinned(p)) {
            u.cloth.setPinned(p, false);
            break;
        }
    u.step();
    EXPECT_FALSE(u.asleep) << "unpinning must wake it";

    World i = settled();
    ASSERT_TRUE(i.asleep);
    i.applyImpulse(i.cloth.x[0], 0.5f, Vec3(0, 0, 1), 1.f);
    i.step();
    EXPECT_FALSE(i.asleep) << "an impulse must wake it";

    World g = settled();
    ASSERT_TRUE(g.asleep);
    g.settings.gravity.x = 3.f;
    g.step();
    EXPECT_FALSE(g.asleep) << "a changed parameter must wake it";

    World off = settled({"sleep.enabled=false"});
    EXPECT_FALSE(off.asleep);
}

// When it falls asleep: a free cloth drifting as one at a constant speed (no gravity, air, springs
// at work, ground or pins) is at rest for sleep while it moves slower than sleep.speed over a frame,
// and falls asleep at the end of the first frame that completes sleep.delay at rest, counted from
// the end of the first frame at rest. With 1/64 s frames (exact in float and double) and a 0.5 s
// delay: after frame 1 + 32 = 33. At twice sleep.speed it never sleeps.
int framesUntilAsleep(float speedFactor) {
    World w;
    Settings& s = w.settings;
    s.gravity = GravitySettings{0.f, 0.f, 0.f};
    s.air.dragCoefficient = 0.f;
    s.material.stretchStiffness = s.material.bendStiffness = 0.f;
    s.collision.ground = false;
    s.tear.enabled = false;
    s.cloth.pin = PinMode::None;
    s.cloth.resolutionX = s.cloth.resolutionY = 6;
    s.time.frameDt = 1.f / 64.f;
    s.time.substeps = 8;
    s.sleep.delay = 0.5f;
    EXPECT_EQ(w.rebuild(), "");
    for (Vec3& v : w.cloth.v)
        v = Vec3(speedFactor * s.sleep.speed, 0.f, 0.f);
    for (int f = 1; f <= 200; ++f) {
        w.step();
        if (w.asleep)
            return f;
    }
    return -1;
}

TEST(Sleep, FallsAsleepAfterTheDelayOnlyWhenSlowerThanTheSpeed) {
    EXPECT_EQ(framesUntilAsleep(0.5f), 33);
    EXPECT_EQ(framesUntilAsleep(2.f), -1) << "a cloth moving faster than sleep.speed must stay awake";
}

// The broad phase only skips triangles that cannot touch a ball: a ball thrown through a tearing
// cloth gives the same state, to the bit, with it and without it (every triangle tested). A 0.2 m
// ball on the 6 m cloth: the grown box holds about 11% of the particles, so the broad phase is the
// one in use (above an eighth it falls back to the full scan).
TEST(BroadPhase, SameResultAsTestingEveryTriangle) {
    auto run = [](bool broad) {
        World w;
        EXPECT_EQ(loadScene(w, "ball-r0.5-v3",
                            std::vector<std::string>{"cloth.resolution_x=40", "cloth.resolution_y=40",
                                                     "ball.radius=0.2"}),
                  "");
        w.settings.collision.broadPhase = broad;
        for (int f = 0; f < 60; ++f)
            w.step();
        EXPECT_GT(w.tearLog.total(), 0u) << "the ball must tear the cloth (contacts with torn triangles)";
        return w;
    };
    const World a = run(true), b = run(false);
    ASSERT_EQ(a.cloth.particleCount(), b.cloth.particleCount());
    EXPECT_EQ(a.cloth.x, b.cloth.x);
    EXPECT_EQ(a.balls[0].x, b.balls[0].x);
}

} // namespace
