// Wind against its formula (the step's wind phase; Onal lists wind among the external forces).
// Per triangle
//   F = c A (n . v_rel) |n . v_rel| n,   v_rel = wind - mean corner velocity,   A = min(area, 2 rest area),
// a third on each corner, with wind = speed x gust factor x direction and the gust factor
//   1 + gust (0.65 sin(ph) + 0.35 sin(2.37 ph + 1.3)),   ph = 2 pi f t.
// A free triangle at rest with no gravity, air drag or springs at work gains, in one sub-step of
// semi-implicit Euler, dv = F / m_corner dt on every corner, with m_corner = rho A_rest / 3:
//   dv = c (A / A_rest) (n . v_rel) |n . v_rel| dt / rho   along n.
// Then a curtain in a steady wind: blown downwind, by about what a flat plate would be.
//
// Section index:
//   [HELPERS]     one free triangle in a wind
//   [TRIANGLE]    the formula, term by term: speed, facing, relative velocity, area, guard, gusts
//   [CLOTH]       a curtain is blown downwind
#include "clothtear/mesh.h"
#include "clothtear/scenes.h"
#include "clothtear/world.h"
#include "quiet_settings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace clothtear;

namespace {

// ========================================================================================== [HELPERS]

struct WindCase {
    float speed = 6.f;  // m/s
    float c = 1.f;      // wind.drag
    Vec3 dir = Vec3(0.f, 0.f, 1.f);
    float density = 0.2f; // kg/m^2
    bool guard = true;
    bool flipped = false; // triangle normal -z instead of +z
};

// One free right triangle with legs of 1 m in the x-y plane, in a wind with no gusts. Springs,
// gravity, air drag, limit, tearing and ground off: only the wind acts (springs at rest give no
// force; a stretched triangle stays in its plane, so its springs give none along z).
World windTriangle(const WindCase& k) {
    World w;
    w.settings = test::quietSettings();
    Settings& s = w.settings;
    s.material.density = k.density;
    s.time.stabilityGuard = k.guard;
    s.wind.enabled = true;
    s.wind.dirX = k.dir.x();
    s.wind.dirY = k.dir.y();
    s.wind.dirZ = k.dir.z();
    s.wind.speed = k.speed;
    s.wind.gust = 0.f;
    s.wind.dragCoefficient = k.c;
    MeshData m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.triangles = {{0, 1, 2}};
    // buildCloth keeps triangles counter-clockwise in UV: mirrored UVs turn the triangle over.
    const double u = k.flipped ? -1.0 : 1.0;
    m.cornerUVs = {{Vec2d(0, 0), Vec2d(u, 0), Vec2d(0, 1)}};
    EXPECT_EQ(w.rebuild(m), "");
    return w;
}

// Unit normal of triangle 0 as the wind phase computes it.
Vec3 normalOf(const World& w) {
    const Triangle& t = w.cloth.triangles[0];
    const Vec3& a = w.cloth.x[t.p[0]];
    return (w.cloth.x[t.p[1]] - a).cross(w.cloth.x[t.p[2]] - a).normalized();
}

double dtOf(const World& w) { return double(w.settings.time.frameDt) / w.settings.time.substeps; }

// The velocity change of every corner in one sub-step from the formula above, along n. `vn` is the
// relative normal speed n . v_rel, `areaRatio` A / A_rest (already capped).
double expectedDv(const World& w, double vn, double areaRatio) {
    return double(w.settings.wind.dragCoefficient) * areaRatio * vn * std::abs(vn) * dtOf(w) /
           double(w.settings.material.density);
}

// Every corner's velocity change over one sub-step, against dv n (to float round-off). Unless
// `springsAtWork` (a stretched triangle), nothing else changes the velocity.
void expectCornersGain(World& w, const Vec3& n, double dv, const std::string& what, bool springsAtWork = false) {
    const std::vector<Vec3> v0 = w.cloth.v;
    w.substep();
    for (Index p = 0; p < 3; ++p) {
        const Vec3 gained = w.cloth.v[p] - v0[p];
        EXPECT_NEAR(gained.dot(n), dv, 1e-5 * std::abs(dv) + 1e-7) << what << ", corner " << p;
        if (!springsAtWork) {
            EXPECT_NEAR((gained - gained.dot(n) * n).norm(), 0.0, 1e-6) << what << ": wind acts along the normal only";
        }
    }
}

// ========================================================================================= [TRIANGLE]

// At rest in a wind along +z: dv = c w^2 dt / rho downwind (+z), whichever way the triangle faces
// (n . v_rel and n change sign together), quadratic in the speed and linear in c. At the defaults
// (c = 1, 6 m/s, 0.2 kg/m^2, dt = 1/600 s) that is 0.3 m/s.
TEST(Wind, FreeTriangleAtRestGainsTheAnalyticVelocityInOneSubStep) {
    for (bool flipped : {false, true})
        for (float speed : {6.f, 3.f})
            for (float c : {1.f, 2.5f}) {
                WindCase k;
                k.flipped = flipped, k.speed = speed, k.c = c;
                World w = windTriangle(k);
                const Vec3 n = normalOf(w);
                ASSERT_NEAR(n.z(), flipped ? -1.f : 1.f, 1e-6f);
                const double dv = expectedDv(w, speed, 1.0); // along +z
                EXPECT_NEAR(dv, c * speed * speed / 600.0 / 0.2, 1e-6 * dv);
                expectCornersGain(w, Vec3(0.f, 0.f, 1.f), dv,
                                  "speed " + std::to_string(speed) + " c " + std::to_string(c) +
                                      (flipped ? " facing -z" : " facing +z"));
                // Semi-implicit Euler: the position moves by the new velocity times dt.
                for (Index p = 0; p < 3; ++p)
                    EXPECT_NEAR(w.cloth.x[p].z(), dv * dtOf(w), 1e-6 * dv * dtOf(w)) << "corner " << p;
            }
}

// The air velocity relative to the cloth is wind - v: a triangle moving downwind at 2 m/s in a
// 6 m/s wind feels 4 m/s (wind + v would be 8 m/s, four times the push); one moving with the wind
// feels nothing; one faster than the wind, or moving into it, is slowed / pushed harder.
TEST(Wind, RelativeAirVelocityIsWindMinusClothVelocity) {
    for (float v0 : {2.f, 6.f, 9.f, -2.f}) {
        World w = windTriangle(WindCase{});
        for (Vec3& v : w.cloth.v) v = Vec3(0.f, 0.f, v0);
        const double vrel = 6.0 - v0;
        expectCornersGain(w, Vec3(0.f, 0.f, 1.f), expectedDv(w, vrel, 1.0), "moving at " + std::to_string(v0) + " m/s");
    }
    // Only the mean corner velocity counts: corners at 0, 3 and 6 m/s feel 6 - 3 m/s.
    World w = windTriangle(WindCase{});
    w.cloth.v[0] = Vec3(0.f, 0.f, 0.f);
    w.cloth.v[1] = Vec3(0.f, 0.f, 3.f);
    w.cloth.v[2] = Vec3(0.f, 0.f, 6.f);
    expectCornersGain(w, Vec3(0.f, 0.f, 1.f), expectedDv(w, 3.0, 1.0), "corners at 0, 3, 6 m/s");
}

// Only the normal component of the wind pushes: along the cloth's plane, nothing; at 60 deg from the
// normal, the push of w cos 60 = w / 2, along the normal (not along the wind).
TEST(Wind, OnlyTheNormalComponentPushesAlongTheNormal) {
    WindCase along;
    along.dir = Vec3(1.f, 0.5f, 0.f);
    World a = windTriangle(along);
    expectCornersGain(a, Vec3(0.f, 0.f, 1.f), 0.0, "wind in the plane");
    WindCase oblique;
    oblique.dir = Vec3(std::sin(float(M_PI) / 3.f), 0.f, std::cos(float(M_PI) / 3.f));
    World o = windTriangle(oblique);
    expectCornersGain(o, Vec3(0.f, 0.f, 1.f), expectedDv(o, 0.5 * 6.0, 1.0), "wind at 60 deg");
}

// The area is the current one, at most twice the rest area: stretched to 1.3x in x and y (area
// 1.69 x rest) the push grows by 1.69; stretched to 2x (area 4 x rest) by 2 only. (The stretched
// springs pull the corners in, in the plane: only the normal part is the wind's.)
TEST(Wind, StretchedTriangleCatchesWindUpToTwiceItsRestArea) {
    for (float scale : {1.3f, 2.f}) {
        World w = windTriangle(WindCase{});
        for (Vec3& x : w.cloth.x) x *= scale;
        const double ratio = std::min(double(scale) * scale, 2.0);
        expectCornersGain(w, Vec3(0.f, 0.f, 1.f), expectedDv(w, 6.0, ratio), "stretched " + std::to_string(scale), true);
    }
}

// Stability guard: the push on a triangle may bring its lightest corner to the air's normal speed
// in one sub-step, never past it. A 0.01 kg/m^2 cloth in a 30 m/s wind would gain
// c w^2 dt / rho = 150 m/s (and explode over a few sub-steps); with the guard it gains 30 m/s.
TEST(Wind, GuardCapsTheGainAtTheRelativeAirSpeed) {
    WindCase k;
    k.speed = 30.f;
    k.density = 0.01f;
    World guarded = windTriangle(k);
    EXPECT_NEAR(expectedDv(guarded, 30.0, 1.0), 150.0, 1e-6 * 150.0);
    expectCornersGain(guarded, Vec3(0.f, 0.f, 1.f), 30.0, "guard on");
    k.guard = false;
    World free = windTriangle(k);
    expectCornersGain(free, Vec3(0.f, 0.f, 1.f), 150.0, "guard off");
}

// Gusts scale the wind speed by the two-sine factor of the simulated time.
TEST(Wind, GustsScaleTheSpeedByTheTwoSineFactor) {
    for (double t : {0.0, 0.3, 1.7}) {
        World w = windTriangle(WindCase{});
        w.settings.wind.gust = 0.5f;
        w.settings.wind.gustFrequency = 0.7f;
        w.time = t;
        const double ph = 2.0 * M_PI * 0.7 * t;
        const double factor = 1.0 + 0.5 * (0.65 * std::sin(ph) + 0.35 * std::sin(2.37 * ph + 1.3));
        expectCornersGain(w, Vec3(0.f, 0.f, 1.f), expectedDv(w, 6.0 * factor, 1.0), "t = " + std::to_string(t));
    }
}

// ============================================================================================ [CLOTH]

// Centre of mass of the cloth, mass-weighted (m).
Vec3d centreOfMass(const World& w) {
    Vec3d sum = Vec3d::Zero();
    double mass = 0;
    for (Index p = 0; p < w.cloth.particleCount(); ++p) {
        sum += w.cloth.particleMass(p) * w.cloth.x[p].cast<double>();
        mass += w.cloth.particleMass(p);
    }
    return sum / mass;
}

// A 2 m curtain pinned along its top edge in a steady 6 m/s wind along +z (no gusts). A flat plate
// hinged at its top settles where the wind's moment balances gravity's:
//   rho g sin(theta) = c w^2 cos(theta)^2   ->   theta = 76.7 deg for rho = 0.2, c = 1, w = 6,
// its centre of mass (L / 2) sin(theta) = 0.97 m downwind. The cloth is no plate (it bellies, and the
// lower part, hanging from the upper, sees the wind at other angles) but must end up of that order:
// well downwind, never upwind, and never farther than half its length stretched to the limit.
// Without wind it stays in its plane.
TEST(Wind, CurtainIsBlownDownwindByAboutWhatAPlateWouldBe) {
    auto run = [](bool wind) {
        World w;
        EXPECT_EQ(loadScene(w, "curtain",
                            std::vector<std::string>{"cloth.resolution_x=16", "cloth.resolution_y=16",
                                                     "tear.enabled=false", "collision.ground=false",
                                                     wind ? "wind.enabled=true" : "wind.enabled=false",
                                                     "wind.gust=0", "wind.speed=6", "wind.dir_x=0", "wind.dir_y=0",
                                                     "wind.dir_z=1"}),
                  "");
        const Vec3d c0 = centreOfMass(w);
        for (int f = 0; f < 120; ++f)
            w.step();
        EXPECT_TRUE(w.finite);
        return Vec3d(centreOfMass(w) - c0);
    };
    const Vec3d still = run(false), blown = run(true);
    EXPECT_NEAR(still.z(), 0.0, 1e-6) << "no wind: the curtain stays in its plane";
    const double plate = 1.0 * std::sin(76.7 * M_PI / 180.0);
    EXPECT_GT(blown.z(), 0.6 * plate) << "moved " << blown.transpose();
    EXPECT_LT(blown.z(), 1.0 * (1.0 + Settings{}.limit.maxStretch)) << "moved " << blown.transpose();
    // Lifted too: the centre of mass rises towards the top edge as the curtain swings up.
    EXPECT_GT(blown.y(), 0.3) << "moved " << blown.transpose();
    RecordProperty("curtain_centre_of_mass_downwind_m", std::to_string(blown.z()));
}

} // namespace
