// Cloth against balls: a fast ball must not pass through the cloth (swept test), and the contact
// exchanges momentum both ways (the ball slows down, the cloth gains what the ball lost).
#include "clothtear/scenes.h"
#include "clothtear/world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace clothtear;

namespace {

// Height (z) of the cloth surface under the point (x, y) of c: the largest z over the triangles
// whose x-y projection contains it; false when no triangle covers it (the cloth swung away).
bool clothZUnder(const Cloth& cloth, const Vec3& c, float& zMin, float& zMax) {
    bool found = false;
    zMin = 1e30f;
    zMax = -1e30f;
    for (const Triangle& t : cloth.triangles) {
        const Vec3& a = cloth.x[t.p[0]];
        const Vec3& b = cloth.x[t.p[1]];
        const Vec3& d = cloth.x[t.p[2]];
        auto cross2 = [](const Vec3& u, const Vec3& v) { return u.x() * v.y() - u.y() * v.x(); };
        const float area = cross2(b - a, d - a);
        if (std::abs(area) < 1e-12f)
            continue;
        const float l1 = cross2(c - a, d - a) / area, l2 = cross2(b - a, c - a) / area, l0 = 1.f - l1 - l2;
        if (l0 < 0.f || l1 < 0.f || l2 < 0.f)
            continue;
        const float z = l0 * a.z() + l1 * b.z() + l2 * d.z();
        zMin = std::min(zMin, z);
        zMax = std::max(zMax, z);
        found = true;
    }
    return found;
}

// A ball of radius 0.1 m and the default ball density, 1 m in front of the cloth's middle on the
// `side` (+1: +z, -1: -z), thrown at it at `speed`.
Ball ballInFrontOf(const World& w, float side, float speed) {
    Ball b;
    b.radius = 0.1f;
    b.mass = w.settings.collision.ballDensity * float(4.0 / 3.0 * M_PI) * b.radius * b.radius * b.radius;
    b.x = Vec3(0.f, 0.f, side * 1.f);
    b.v = Vec3(0.f, 0.f, -side * speed);
    return b;
}

struct ThrowResult {
    bool passedThrough = false; // the ball centre got behind the cloth surface under it
    int frame = -1;             // first frame where it did
    float speedAfter = 0;       // |v| of the ball at the end
};

// Steps `frames` frames, checking after every sub-step that the ball centre stays on its own side
// of the cloth surface directly under it (the ball may still leave by going around an edge).
ThrowResult throwBall(World& w, float side, int frames) {
    ThrowResult r;
    for (int f = 0; f < frames && !r.passedThrough; ++f) {
        for (int s = 0; s < w.settings.time.substeps; ++s) {
            w.substep();
            float zMin, zMax;
            const Vec3 c = w.balls[0].x;
            if (clothZUnder(w.cloth, c, zMin, zMax) && (side > 0 ? c.z() < zMin : c.z() > zMax)) {
                r.passedThrough = true;
                r.frame = f;
                break;
            }
        }
    }
    r.speedAfter = w.balls[0].v.norm();
    return r;
}

// The swept test alone: a fully pinned cloth is a wall. At one sub-step per 60 Hz frame the ball
// moves 0.33 m per step, more than its diameter, so a test of the end position only would let it
// through; the segment-triangle test must stop it on its own side with no normal velocity left.
// Aimed at the middle of a quad (on the diagonal two triangles share), at a particle, at an
// edge and at an arbitrary point.
TEST(Collision, FastBallDoesNotTunnelThroughAPinnedCloth) {
    const float h = 2.f / 39.f; // particle spacing of the default 40 x 40 curtain
    const Vec3 aims[] = {
        {0.f, 0.f, 0.f}, {0.5f * h, 0.5f * h, 0.f}, {0.5f * h, 0.f, 0.f}, {0.0123f, -0.0311f, 0.f}};
    for (float side : {1.f, -1.f})
        for (const Vec3& aim : aims) {
            World w;
            ASSERT_EQ(
                loadScene(w, "curtain",
                          std::vector<std::string>{"time.substeps=1", "gravity.y=0", "tear.enabled=false"}),
                "");
            for (Index p = 0; p < w.cloth.particleCount(); ++p)
                w.cloth.setPinned(p, true);
            Ball ball = ballInFrontOf(w, side, 20.f);
            ball.x += aim;
            w.balls.push_back(ball);
            const ThrowResult r = throwBall(w, side, 30);
            const std::string where = "side " + std::to_string(side) + " aim (" + std::to_string(aim.x()) +
                                      ", " + std::to_string(aim.y()) + ")";
            EXPECT_FALSE(r.passedThrough) << where << ", frame " << r.frame;
            const Ball& b = w.balls[0];
            // Resting against the wall at its radius plus the cloth thickness, its normal speed gone,
            // not shoved sideways.
            EXPECT_NEAR(side * b.x.z(), b.radius + w.settings.collision.thickness, 1e-3f) << where;
            EXPECT_LT(std::abs(b.v.z()), 1e-3f) << where;
            EXPECT_LT((b.x - Vec3(aim.x(), aim.y(), b.x.z())).norm(), 1e-3f) << where;
        }
}

// Two-way momentum: a free cloth (no pins, gravity, air or ground) hit by a ball. The contact
// impulse on the cloth is the one taken from the ball and the springs are internal, so the total
// momentum stays put (limit off: the averaged Jacobi limit does not conserve momentum, see
// test_physics.cpp) while the ball slows down and the cloth picks up what it lost.
TEST(Collision, BallAndFreeClothExchangeMomentum) {
    World w;
    ASSERT_EQ(loadScene(w, "curtain",
                        std::vector<std::string>{"cloth.pin=none", "gravity.y=0", "air.drag=0",
                                                 "collision.ground=false", "limit.enabled=false",
                                                 "tear.enabled=false"}),
              "");
    w.balls.push_back(ballInFrontOf(w, 1.f, 20.f));
    auto momentum = [&] {
        Vec3d p = w.balls[0].mass * w.balls[0].v.cast<double>();
        for (Index i = 0; i < w.cloth.particleCount(); ++i)
            p += w.cloth.particleMass(i) * w.cloth.v[i].cast<double>();
        return p;
    };
    const Vec3d p0 = momentum();
    for (int f = 0; f < 20; ++f)
        w.step();
    ASSERT_TRUE(w.finite);
    const Vec3d p1 = momentum();
    EXPECT_LT((p1 - p0).norm(), 1e-4 * p0.norm())
        << "momentum before " << p0.transpose() << ", after " << p1.transpose();
    EXPECT_LT(std::abs(w.balls[0].v.z()), 19.f) << "the ball must slow down";
    double clothPz = 0;
    for (Index i = 0; i < w.cloth.particleCount(); ++i)
        clothPz += w.cloth.particleMass(i) * w.cloth.v[i].z();
    EXPECT_LT(clothPz, -0.05 * std::abs(p0.z())) << "the cloth must be pushed along -z";
}

// The scenario: a 0.1 m ball at 20 m/s thrown at the middle of the curtain at 60 Hz with
// the default sub-steps (tearing off so the cloth cannot legitimately let it through). After 1 s
// the ball must still be on its own side of the cloth surface under it, and slower.
//
// It used to fail, from either side, for balls heavier than a few tens of grams (0.84 kg here): the
// contact pushed the struck cloth ahead of the ball, the limit snapped a triangle back through the
// ball centre, and a side judged from the ball's segment alone put the ball out on the far side.
// What holds it now (collide.cpp): sides are judged relative to the moving cloth (the ball's start
// against where the triangle started), the limit lets a ball stretch the springs it touches up to
// the tear threshold, and the contact phase after the limit makes the ball give way where the
// cloth held.
TEST(Collision, FastBallDoesNotPassThroughTheCurtain) {
    for (float side : {1.f, -1.f}) {
        World w;
        ASSERT_EQ(loadScene(w, "curtain", std::vector<std::string>{"tear.enabled=false"}), "");
        ASSERT_EQ(w.settings.time.frameDt, 1.f / 60.f);
        w.balls.push_back(ballInFrontOf(w, side, 20.f));
        const ThrowResult r = throwBall(w, side, 60);
        EXPECT_FALSE(r.passedThrough) << "side " << side << ": through at frame " << r.frame;
        EXPECT_TRUE(w.finite);
        EXPECT_LT(r.speedAfter, 0.5f * 20.f) << "side " << side;
    }
}

// The fabric a ball stretches is a band in metres (collision.stretch_band, limit.cpp
// markStretchBand), not the one ring of springs its contact touches: the app's default throw (2 kg,
// 0.5 m, 8 m/s, square on at the middle) tears the curtain in the same frame and goes through at the
// same speed at two resolutions and two sizes. With only the contact's ring (stretch_band 0) the
// finer curtain held the ball: at 96 a side the 2 m curtain first tore 2 frames later and left it
// 5.4 m/s against 7.2 at 40; the 4 m one at 128 a side, 4.2 against 7.2 at 64
// (bench/README.md, "The fabric a ball stretches"). Only 64 and 128 are within 10 % at 4 m: over 48-160
// a side the ball leaves at 6.88 / 7.02 / 6.44 / 6.46 / 6.49 / 6.48 / 5.94 m/s on one thread (160: 18 %
// below 64; bench/README.md, "The gauge's line held as a whole").
// One throw sits on round-off: the 4 m curtain's first tear comes at 0.117, 0.133 or 0.150 s at 64
// and at 128 a side with gravity 1e-5 or 1e-6 m/s^2 stronger or weaker, and the ball leaves at
// 6.1-7.0 m/s (on one thread, on two, and with the limit's two-thread order: bench/README.md,
// "Gauss-Seidel by regions"). So each resolution is thrown five times, with gravity so apart, and
// the medians are compared.
struct BandThrow {
    double firstTear = -1; // s
    float speed = 0;       // m/s, the ball's z speed 0.6 s after the throw
    float z = 0;           // m, where it is then (the curtain hangs at z = 0)
};

BandThrow throwThroughTheCurtain(const std::string& size, int res, const std::string& band,
                                 const std::string& gravity = "-9.81") {
    World w;
    const std::string r = std::to_string(res);
    EXPECT_EQ(loadScene(w, "curtain",
                        std::vector<std::string>{"cloth.width=" + size, "cloth.height=" + size, "cloth.resolution_x=" + r,
                                                 "cloth.resolution_y=" + r, "collision.stretch_band=" + band,
                                                 "gravity.y=" + gravity}),
              "");
    Ball b; // the ball tool's default, square on at the middle
    b.x = Vec3(0.f, 0.f, 1.f);
    b.v = Vec3(0.f, 0.f, -8.f);
    w.balls.push_back(b);
    BandThrow t;
    while (w.time < 0.6) {
        w.step();
        if (t.firstTear < 0 && w.tearLog.total() > 0) t.firstTear = w.time;
    }
    t.speed = -w.balls[0].v.z();
    t.z = w.balls[0].x.z();
    EXPECT_TRUE(w.finite);
    return t;
}

TEST(Collision, ABallStretchesTheSameBandOfFabricAtEveryResolution) {
    struct Case {
        const char* size;
        int coarse, fine;
    };
    // The median first tear, speed and place of five throws whose gravity differs by round-off.
    auto medianThrow = [](const char* size, int res) {
        std::vector<BandThrow> t;
        for (const char* g : {"-9.81", "-9.81001", "-9.80999", "-9.8101", "-9.8099"})
            t.push_back(throwThroughTheCurtain(size, res, "0.05", g));
        auto median = [&](auto field) {
            std::vector<double> v;
            for (const BandThrow& b : t) v.push_back(double(field(b)));
            std::sort(v.begin(), v.end());
            return v[v.size() / 2];
        };
        BandThrow m;
        m.firstTear = median([](const BandThrow& b) { return b.firstTear; });
        m.speed = float(median([](const BandThrow& b) { return b.speed; }));
        m.z = float(median([](const BandThrow& b) { return b.z; }));
        return m;
    };
    for (const Case& c : {Case{"2", 40, 96}, Case{"4", 64, 128}}) {
        const BandThrow a = medianThrow(c.size, c.coarse), b = medianThrow(c.size, c.fine);
        const std::string what = std::string(c.size) + " m curtain at " + std::to_string(c.coarse) + " and " +
                                 std::to_string(c.fine) + " a side";
        std::printf("%s, medians: first tear %.3f / %.3f s, ball %.2f / %.2f m/s at z %.2f / %.2f m\n", what.c_str(), a.firstTear,
                    b.firstTear, a.speed, b.speed, a.z, b.z);
        EXPECT_GT(a.firstTear, 0.0) << what;
        EXPECT_GT(b.firstTear, 0.0) << what;
        EXPECT_LE(std::abs(a.firstTear - b.firstTear), 1.0 / 60.0 + 1e-6) << what << ": the first tear within a frame";
        EXPECT_NEAR(b.speed, a.speed, 0.1f * a.speed) << what << ": the ball goes through as fast";
        EXPECT_LT(b.z, -2.f) << what << ": through the curtain";
    }
}

} // namespace
