// Sleep (src/core/sleep.cpp) and the ball broad phase (src/core/collide.cpp, trianglesIn): what
// they skip must not change what is simulated.
#include "clothtear/knife.h"
#include "clothtear/params.h"
#include "clothtear/pieces.h"
#include "clothtear/scenes.h"
#include "clothtear/world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
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

// ---- torn pieces (src/core/step/piece_sleep.cpp) -------------------------------------------------

namespace {

// The curtain (2 m, pinned along its top) cut across 0.6 m above its hem after one frame: the strip
// below falls to the ground and settles there while the rest swings.
World cutCurtain(int res, std::vector<std::string> extra = {}) {
    World w;
    const std::string r = std::to_string(res);
    std::vector<std::string> o = {"cloth.resolution_x=" + r, "cloth.resolution_y=" + r};
    o.insert(o.end(), extra.begin(), extra.end());
    EXPECT_EQ(loadScene(w, "curtain", o), "");
    w.step();
    const CutResult cut = w.cut({Vec2d(-1.2, -0.4), Vec2d(1.2, -0.4)});
    EXPECT_GT(cut.particlesAdded, 0u);
    EXPECT_EQ(findPieces(w.cloth).size(), 2u);
    return w;
}

size_t piecesAsleep(const World& w) {
    size_t n = 0;
    for (const Piece& p : findPieces(w.cloth)) n += p.asleep;
    return n;
}

// Steps until a piece sleeps (at most `frames`); returns the frames stepped, -1 if none slept.
int stepUntilAPieceSleeps(World& w, int frames) {
    for (int f = 1; f <= frames; ++f) {
        w.step();
        if (piecesAsleep(w) > 0) return f;
    }
    return -1;
}

} // namespace

// The strip cut off sleeps once it has lain still for sleep.delay, at 16 and 32 a side (after 5.6 s
// at both when written): then its particles have no inverse mass and no velocity and do not move, it
// is the piece on the ground (the smaller one, with no pin), and while a hand pulls the curtain
// above it about, the curtain is simulated and the strip sleeps on.
TEST(PieceSleep, ATornOffStripSleepsOnTheGroundWhileTheCurtainSwings) {
    for (int res : {16, 32}) {
        World w = cutCurtain(res);
        const int frames = stepUntilAPieceSleeps(w, 6 * 60);
        ASSERT_GT(frames, 0) << res << ": no piece fell asleep in 6 s";
        EXPECT_GT(frames, 60) << res << ": it falls 2 m and then lies still for sleep.delay (1 s) first";
        const std::vector<Piece> pieces = findPieces(w.cloth);
        ASSERT_EQ(pieces.size(), 2u);
        EXPECT_FALSE(pieces[0].asleep) << res << ": the pinned curtain";
        EXPECT_TRUE(pieces[1].asleep) << res;
        EXPECT_NEAR(pieces[1].restArea, 2.0 * 0.6, 0.1) << res << ": the strip below the cut";
        std::vector<Index> strip;
        for (Index p = 0; p < w.cloth.particleCount(); ++p)
            if (w.cloth.asleep(p)) strip.push_back(p);
        float lowest = 1e30f;
        for (Index p : strip) {
            EXPECT_FALSE(w.cloth.pinned(p));
            EXPECT_EQ(w.cloth.invMass[p], 0.f);
            EXPECT_EQ(w.cloth.v[p], Vec3::Zero());
            lowest = std::min(lowest, w.cloth.x[p].y());
        }
        EXPECT_LT(lowest, w.settings.collision.groundHeight + 0.05f) << res << ": it rests on the ground";
        EXPECT_FALSE(w.asleep) << res << ": the curtain has not settled yet";
        // A hand pulls the curtain about: the strip on the ground sleeps on.
        Index held = kNone;
        for (Index p = 0; p < w.cloth.particleCount() && held == kNone; ++p)
            if (!w.cloth.asleep(p) && !w.cloth.pinned(p)) held = p;
        ASSERT_NE(held, kNone);
        w.cloth.setPinned(held, true);
        w.drivers.push_back(Driver{{held}, Vec3(0.f, 0.f, 0.5f)});
        const std::vector<Vec3> x = w.cloth.x;
        const uint64_t substeps = w.profile.substeps;
        uint64_t guardSubsteps = 0; // the hand may tear the curtain, and a tear may change the guard's step
        for (int f = 0; f < 30; ++f) {
            w.step();
            guardSubsteps += uint64_t(w.frameSubsteps);
        }
        for (Index p : strip) EXPECT_EQ(w.cloth.x[p], x[p]);
        EXPECT_EQ(piecesAsleep(w), 1u) << res;
        EXPECT_EQ(w.profile.substeps - substeps, guardSubsteps) << res << ": the World is simulated";
        EXPECT_NEAR((w.cloth.x[held] - x[held]).z(), 0.25f, 1e-3f) << res << ": and the hand moved the curtain";
        std::cout << res << " a side: the strip sleeps after " << frames << " frames, " << strip.size() << " particles\n";
    }
}

// Whatever can move a sleeping strip wakes it: a hand grabbing one of its particles (a driver),
// a ball coming near, a changed parameter, an impulse. Awake, it moves again.
TEST(PieceSleep, WakesForAHandABallAParameterAndAnImpulse) {
    World asleep = cutCurtain(16);
    ASSERT_GT(stepUntilAPieceSleeps(asleep, 6 * 60), 0);
    Index grabbed = kNone;
    for (Index p = 0; p < asleep.cloth.particleCount() && grabbed == kNone; ++p)
        if (asleep.cloth.asleep(p)) grabbed = p;
    ASSERT_NE(grabbed, kNone);

    World hand = asleep;
    hand.cloth.setPinned(grabbed, true);
    hand.drivers.push_back(Driver{{grabbed}, Vec3(0.f, 1.f, 0.f)});
    const Vec3 before = hand.cloth.x[grabbed];
    hand.step();
    EXPECT_EQ(piecesAsleep(hand), 0u) << "a hand";
    EXPECT_GT((hand.cloth.x[grabbed] - before).norm(), 0.01f);

    World ball = asleep;
    ball.step();
    EXPECT_EQ(piecesAsleep(ball), 1u) << "nothing near: it sleeps on";
    Ball b;
    b.radius = 0.2f;
    b.x = ball.cloth.x[grabbed] + Vec3(0.f, 0.5f, 0.f);
    b.v = Vec3(0.f, -5.f, 0.f);
    ball.balls.push_back(b);
    ball.step();
    EXPECT_EQ(piecesAsleep(ball), 0u) << "a ball";

    World param = asleep;
    ASSERT_EQ(setParamFromString(param.settings, "gravity.x", "3"), "");
    param.step();
    EXPECT_EQ(piecesAsleep(param), 0u) << "a parameter";
    for (int f = 0; f < 10; ++f) param.step();
    EXPECT_GT(std::abs(param.cloth.x[grabbed].x() - asleep.cloth.x[grabbed].x()), 0.001f) << "sideways gravity moves it";

    World impulse = asleep;
    impulse.applyImpulse(impulse.cloth.x[grabbed], 0.2f, Vec3(0.f, 1.f, 0.f), 1.f);
    EXPECT_EQ(piecesAsleep(impulse), 0u) << "an impulse";
    EXPECT_GT(impulse.cloth.v[grabbed].y(), 0.5f);
}

// With sleep off, or in wind, no piece sleeps.
TEST(PieceSleep, NeverWithSleepOffOrInWind) {
    World off = cutCurtain(16, {"sleep.enabled=false"});
    EXPECT_EQ(stepUntilAPieceSleeps(off, 4 * 60), -1);
    World wind = cutCurtain(16, {"wind.enabled=true", "wind.speed=1"});
    EXPECT_EQ(stepUntilAPieceSleeps(wind, 4 * 60), -1);
}
