// Sleep of balls (src/core/step/ball_sleep.cpp): a ball at rest with no moving cloth within its
// reach sleeps; the ball phases skip it and the cloth takes the step it takes without a ball; it
// wakes when something within its reach moves.
#include "curtain_world.h"
#include "clothtear/scenes.h"
#include "clothtear/state_hash.h"
#include "clothtear/world_file.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace clothtear;
using clothtear::test::curtainWorld;

namespace {

size_t asleepParticles(const World& w) {
    size_t count = 0;
    for (Index p = 0; p < w.cloth.particleCount(); ++p) count += w.cloth.asleep(p);
    return count;
}

// The curtain with its bottom strip cut off (knife) and settled asleep on the ground, and a ball
// lying still on the ground against the strip's edge: how the ball tool's throw ends,
// the ball by the piece it tore out. The ball wakes the strip; once the ball has been still for
// sleep.delay it no longer keeps the strip awake, the strip sleeps again, then the ball.
struct BallByPiece {
    World world;
    Vec3 stripLo, stripHi;
};
BallByPiece ballBesideASleepingPiece(int n) {
    BallByPiece s{curtainWorld(n), Vec3::Constant(1e30f), Vec3::Constant(-1e30f)};
    World& w = s.world;
    w.step();
    EXPECT_GT(w.cut({Vec2d(-1.2, -0.4), Vec2d(1.2, -0.4)}).particlesAdded, 0u);
    // Tipped backwards as it falls, the strip lies flat (straight down it lands standing on its edge).
    for (Index p = 0; p < w.cloth.particleCount(); ++p)
        if (w.cloth.x[p].y() < -0.45f) w.cloth.v[p].z() += 1.f;
    for (int f = 0; f < 900 && asleepParticles(w) == 0; ++f) w.step();
    EXPECT_GT(asleepParticles(w), 0u) << "the strip falls asleep on the ground";
    for (Index p = 0; p < w.cloth.particleCount(); ++p)
        if (w.cloth.asleep(p)) {
            s.stripLo = s.stripLo.cwiseMin(w.cloth.x[p]);
            s.stripHi = s.stripHi.cwiseMax(w.cloth.x[p]);
        }
    Ball b;
    b.radius = 0.3f;
    b.mass = 2.f;
    b.x = Vec3(0.5f * (s.stripLo.x() + s.stripHi.x()), w.settings.collision.groundHeight + b.radius,
               s.stripLo.z() - b.radius + 0.005f); // against the strip's edge
    w.balls.push_back(b);
    return s;
}

// Something else keeps the World awake: the curtain is nudged at its middle every frame, far above
// the ball.
void nudgedStep(World& w) {
    w.cloth.v[w.cloth.particleCount() / 3].z() += 0.5f;
    w.step();
}

int framesUntilTheBallSleeps(World& w, int most) {
    for (int f = 0; f < most; ++f) {
        if (w.balls[0].asleep) return f;
        nudgedStep(w);
    }
    return w.balls[0].asleep ? most : -1;
}

} // namespace

// The ball wakes the strip; awake beside the cloth, it takes the guard's conservative step (more
// sub-steps than the curtain alone). The ball and the strip are still; after sleep.delay the strip
// sleeps, and in the same frame the ball. From then on no ball phase runs, the frame takes the
// sub-steps of the curtain without a ball (the guard's budget, not its per-spring caps), and the
// ball stays where it lay. At 32 and 64 particles a side.
TEST(BallSleep, ABallBesideASleepingPieceSleepsAndThenCostsNothing) {
    for (int n : {32, 64}) {
        BallByPiece s = ballBesideASleepingPiece(n);
        World& w = s.world;
        World withoutBall = w;
        withoutBall.balls.clear();
        nudgedStep(w), nudgedStep(withoutBall);
        EXPECT_EQ(asleepParticles(w), 0u) << n << ": the ball woke the strip";
        for (int f = 1; f < 30; ++f) nudgedStep(w), nudgedStep(withoutBall);
        ASSERT_FALSE(w.balls[0].asleep) << n;
        EXPECT_GT(w.frameSubsteps, withoutBall.frameSubsteps) << n << ": an awake ball near the cloth";
        const int sleptAfter = framesUntilTheBallSleeps(w, 600);
        ASSERT_GT(sleptAfter, 0) << n << ": the ball never slept";
        // Still for sleep.delay (60 frames from the first), with the strip beside it.
        EXPECT_GE(sleptAfter, 60 - 30 - 1) << n;
        EXPECT_LE(sleptAfter, 2 * 60 - 30 + 2) << n;
        EXPECT_GT(asleepParticles(w), 0u) << n << ": it sleeps beside a sleeping strip";
        EXPECT_EQ(w.balls[0].v, Vec3::Zero()) << n;
        const Vec3 lay = w.balls[0].x;
        for (int f = 0; f < sleptAfter; ++f) nudgedStep(withoutBall); // the same frames without the ball
        const uint64_t collideRuns = w.profile.runs[int(Phase::Collide)];
        for (int f = 0; f < 5; ++f) nudgedStep(w), nudgedStep(withoutBall);
        EXPECT_FALSE(w.asleep) << n << ": the nudged curtain keeps the World awake";
        EXPECT_EQ(w.profile.runs[int(Phase::Collide)], collideRuns) << n << ": no ball phase while it sleeps";
        EXPECT_EQ(w.frameSubsteps, withoutBall.frameSubsteps) << n << ": the curtain's own step";
        EXPECT_TRUE(w.balls[0].asleep) << n;
        EXPECT_EQ(w.balls[0].x, lay) << n;
        EXPECT_TRUE(w.finite) << n;
    }
}

// A sleeping ball wakes when the cloth within its reach moves: a second ball dropped on the strip
// wakes the strip, and the strip the first ball. And a ball given a velocity wakes by itself.
TEST(BallSleep, ASleepingBallWakesWhenTheClothBesideItMovesOrItIsPushed) {
    BallByPiece s = ballBesideASleepingPiece(32);
    World& w = s.world;
    ASSERT_GT(framesUntilTheBallSleeps(w, 600), 0);
    Ball second = w.balls[0];
    second.asleep = false;
    second.stillFrames = 0;
    const Vec3 middle = 0.5f * (s.stripLo + s.stripHi);
    second.x = Vec3(middle.x(), s.stripHi.y() + 0.6f, middle.z());
    second.v = Vec3(0.f, -3.f, 0.f);
    w.balls.push_back(second);
    int wokeAt = -1;
    for (int f = 0; f < 30 && wokeAt < 0; ++f) {
        nudgedStep(w);
        if (!w.balls[0].asleep) wokeAt = f;
    }
    EXPECT_GE(wokeAt, 0) << "the strip the second ball hit wakes the first";
    EXPECT_EQ(asleepParticles(w), 0u);

    BallByPiece t = ballBesideASleepingPiece(32);
    World& v = t.world;
    ASSERT_GT(framesUntilTheBallSleeps(v, 600), 0);
    const Vec3 lay = v.balls[0].x;
    v.balls[0].v = Vec3(0.f, 3.f, 0.f); // tossed up by hand
    nudgedStep(v);
    EXPECT_FALSE(v.balls[0].asleep);
    EXPECT_GT(v.balls[0].x.y(), lay.y());
}

// While the World sleeps, a ball that cannot reach the cloth still falls and bounces on the ground
// (it hung where it was), and then sleeps itself.
TEST(BallSleep, ABallBesideASleepingWorldFallsToTheGroundAndSleeps) {
    World w = curtainWorld(16);
    for (int f = 0; f < 900 && !w.asleep; ++f) w.step();
    ASSERT_TRUE(w.asleep);
    Ball b;
    b.radius = 0.2f;
    b.x = Vec3(5.f, 0.f, 0.f); // 4 m beside the curtain, 2.8 m above the ground
    w.balls.push_back(b);
    const float floor = w.settings.collision.groundHeight + b.radius;
    for (int f = 0; f < 40; ++f) w.step();
    EXPECT_NEAR(w.balls[0].x.y(), -0.5f * 9.81f * (40.f / 60.f) * (40.f / 60.f), 0.02f) << "falling freely";
    for (int f = 40; f < 150; ++f) w.step();
    EXPECT_TRUE(w.asleep);
    EXPECT_NEAR(w.balls[0].x.y(), floor, 1e-3f) << "the bounces (restitution 0.3) have died down by 2.5 s";
    int sleptAt = -1;
    for (int f = 0; f < 240 && sleptAt < 0; ++f) {
        w.step();
        if (w.balls[0].asleep) sleptAt = f;
    }
    EXPECT_GE(sleptAt, 0);
    EXPECT_EQ(w.balls[0].x.y(), floor);
}

// A ball resting in a cloth the pins hold (the thesis's slow 1 m ball, which must stay on the
// sheet) never sleeps: the cloth under it is awake. Its outcome is that of a ball that never sleeps.
TEST(BallSleep, ABallInAHangingClothNeverSleeps) {
    World w;
    const std::vector<std::string> sets{"cloth.resolution_x=32", "cloth.resolution_y=32"};
    ASSERT_EQ(loadScene(w, "ball-r1-v3-low", sets), "");
    for (int f = 0; f < 240; ++f) {
        w.step();
        ASSERT_FALSE(w.balls[0].asleep) << "frame " << f;
    }
}

// Saved half a second before the ball sleeps, the copy puts it to sleep on the same frame (its
// still frames are in the file, version 5); saved asleep, it sleeps on.
TEST(BallSleep, ASettlingBallContinuesBitForBitAfterALoad) {
    BallByPiece s = ballBesideASleepingPiece(32);
    World reference = s.world;
    const int sleepsAfter = framesUntilTheBallSleeps(reference, 600);
    ASSERT_GT(sleepsAfter, 30);
    World& w = s.world;
    for (int f = 0; f < sleepsAfter - 30; ++f) nudgedStep(w);
    ASSERT_FALSE(w.balls[0].asleep);
    std::string bytes;
    ASSERT_EQ(serializeWorld(w, bytes), "");
    Result<World> copy = parseWorld(bytes, "w.ctw");
    ASSERT_TRUE(copy.ok()) << copy.error;
    for (int f = 0; f < 60; ++f) {
        nudgedStep(w);
        nudgedStep(copy.value);
        ASSERT_EQ(stateHash(copy.value), stateHash(w)) << "frame " << f + 1;
        ASSERT_EQ(copy.value.balls[0].asleep, w.balls[0].asleep) << "frame " << f + 1;
        ASSERT_EQ(copy.value.balls[0].stillFrames, w.balls[0].stillFrames) << "frame " << f + 1;
    }
    EXPECT_TRUE(w.balls[0].asleep);
}
