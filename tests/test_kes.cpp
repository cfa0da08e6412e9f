// material.model = kes (include/clothtear/kes.h, docs/kes-material.md): the units, the tensile law,
// the hysteretic bending rate model and its hinge, against values computed by hand from Tagawa's
// printed coefficients; the hysteresis loop of a strip bent back and forth (the energy the law says
// a cycle loses, at two resolutions; none for the linear model; the reversal threshold that keeps
// sub-step jitter from eating the loop); the stability guard with the law's
// tangent; the hinges' memory through a save, a load and a rewind; tearing with the kes law; implicit
// Euler with the law's Jacobian (a hanging strip's static drop, large steps, the hinge's tangent);
// forward Euler's Rayleigh damping of the law on one mode.
#include "clothtear/history.h"
#include "clothtear/kes.h"
#include "clothtear/mesh.h"
#include "clothtear/params.h"
#include "clothtear/scenes.h"
#include "clothtear/state_hash.h"
#include "clothtear/world_file.h"
#include "quiet_settings.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace clothtear;

namespace {

World scene(const char* name, std::vector<std::string> sets) {
    World w;
    EXPECT_EQ(loadScene(w, name, sets), "") << name;
    return w;
}

} // namespace

// gf/cm = 0.980665 N/m; at 1 % strain Tagawa's polynomial gives 0.1191 + 8.5748 = 8.6939 gf/cm.
TEST(Kes, TensionInSiFromThePrintedCoefficients) {
    const KesLaw law = kesLawSI(MaterialSettings{});
    EXPECT_NEAR(kesTension(law, 0.01), 8.6939 * 0.980665, 1e-4);
    // 5 %: 0.1191 * 625 + 8.5748 * 25 = 288.8075 gf/cm.
    EXPECT_NEAR(kesTension(law, 0.05), 288.8075 * 0.980665, 1e-3);
    EXPECT_NEAR(kesTension(law, -0.05), -288.8075 * 0.980665, 1e-3) << "compression mirrors extension";
    // The tangent is the derivative (per unit strain, not per %).
    for (double e : {0.004, 0.03, 0.1}) {
        const double h = 1e-6, fd = (kesTension(law, e + h) - kesTension(law, e - h)) / (2 * h);
        EXPECT_NEAR(kesTangent(law, e), fd, 1e-6 * std::max(1.0, fd)) << e;
    }
    EXPECT_EQ(kesTangent(law, 0.0), 0.0) << "the fit has no linear term: no stiffness at rest";
    EXPECT_DOUBLE_EQ(kesMaxTangent(law, 0.1), kesTangent(law, 0.1));
    // Bending: D = 0.12266 gf cm^2/cm = 1.2029e-5 N m, D1 = 0.1181 gf = 1.1582e-3 N, alpha = 0.2494 m.
    EXPECT_NEAR(law.D, 0.12266 * 9.80665e-5, 1e-12);
    EXPECT_NEAR(law.D1, 0.1181 * 9.80665e-3, 1e-10);
    EXPECT_NEAR(law.alpha, 0.2494, 1e-7);
}

// The virgin curve, a reversal that keeps M continuous, and the steady loop's area (Eq. 4).
TEST(Kes, RateModelBranchesAndLoopArea) {
    const KesLaw law = kesLawSI(MaterialSettings{});
    BendMemory m;
    const double K1 = 30.0; // 1/m (0.3 cm^-1)
    const double M1 = kesBendAdvance(law, m, K1);
    EXPECT_NEAR(M1, law.D * K1 + law.D1 * (1 - std::exp(-law.alpha * K1)), 1e-12) << "virgin curve";
    // Unloading: just after the reversal, M follows the new branch from (K1, M1) down.
    const double M2 = kesBendAdvance(law, m, K1 - 1.0);
    EXPECT_EQ(m.direction, -1);
    EXPECT_FLOAT_EQ(m.reversalK, float(K1));
    EXPECT_NEAR(M2, M1 - law.D - law.D1 * (1 - std::exp(-law.alpha)), 1e-6);
    // A closed cycle -Km .. Km .. -Km after one to settle: its area, summed by the trapezoid rule.
    for (double Km : {5.0, 50.0, 150.0}) {
        BendMemory mem;
        const int n = 20000;
        double area = 0, lastK = 0, lastM = 0;
        for (int i = 0; i <= 2 * n; ++i) {
            const double K = Km * std::sin(2 * M_PI * i / n);
            const double M = kesBendAdvance(law, mem, K);
            if (i > n) area += 0.5 * (M + lastM) * (K - lastK);
            lastK = K, lastM = M;
        }
        const double expected = kesLoopEnergyPerArea(law, Km);
        EXPECT_GT(expected, 0);
        EXPECT_NEAR(area, expected, 2e-3 * expected) << "Km = " << Km; // the work put in and lost
    }
    // Large alpha Km: the loop is a parallelogram of height D1 less the rounding of its corners.
    EXPECT_NEAR(kesLoopEnergyPerArea(law, 250.0), law.D1 * (500.0 - 2 / law.alpha), 1e-12);
}

namespace {
// The area of the M-K loop of one hinge over the second of two cycles K = Km sin(2 pi i / n) + the
// jitter (-1)^i j (a sub-step's back-and-forth), trapezoid rule.
double loopAreaWithJitter(const KesLaw& law, double Km, double jitter) {
    BendMemory mem;
    const int n = 20000;
    double area = 0, lastK = 0, lastM = 0;
    for (int i = 0; i <= 2 * n; ++i) {
        const double K = Km * std::sin(2 * M_PI * i / n) + (i % 2 ? -jitter : jitter);
        const double M = kesBendAdvance(law, mem, K);
        if (i > n) area += 0.5 * (M + lastM) * (K - lastK);
        lastK = K, lastM = M;
    }
    return area;
}
} // namespace

// material.kes_bend_reversal: a back-and-forth smaller than the threshold retraces one curve and the
// large loop keeps the area the law gives (Eq. 4). Without the threshold the same jitter starts a
// branch at every sample: the hinge stays on the steep starts of its branches and the loop shrinks
// (forward Euler's swing did not decay: docs/kes-material.md, "Reversals and jitter").
TEST(Kes, JitterBelowTheReversalThresholdKeepsTheLargeLoop) {
    const KesLaw law = kesLawSI(MaterialSettings{});
    ASSERT_GT(law.reversal, 0.0) << "the default has a threshold";
    // Back-steps of up to 0.2 x the threshold (0.06 1/m: most of semi-implicit Euler's sub-step
    // jitter in swing-vacuum is this size, bench/README.md).
    const double jitter = 0.1 * law.reversal;
    for (double Km : {15.0, 50.0}) { // the swing's curvature at release, and a saturated loop
        const double expected = kesLoopEnergyPerArea(law, Km);
        // Within 3 %: each jitter moves the extreme on by a sample's step, so the tentative branches
        // it retraces start from slightly different points (a sliver of loop per jitter: 2 % here,
        // in proportion to the jitter's size).
        EXPECT_NEAR(loopAreaWithJitter(law, Km, jitter), expected, 0.03 * expected) << "Km = " << Km;
        KesLaw plain = law;
        plain.reversal = 0;
        EXPECT_NEAR(loopAreaWithJitter(plain, Km, 0.0), expected, 0.002 * expected) << "no jitter: the same loop";
        const double lost = loopAreaWithJitter(plain, Km, jitter);
        EXPECT_LT(lost, 0.5 * expected) << "Km = " << Km << ": every jitter a branch";
    }
    // Within the threshold the memory does not move; past it the reversal counts at the extreme, and
    // M is continuous there (the tentative branch is the committed one).
    BendMemory mem;
    kesBendAdvance(law, mem, 10.0);
    const BendMemory at10 = mem;
    const double tentative = kesBendAdvance(law, mem, 10.0 - 0.9 * law.reversal);
    EXPECT_EQ(mem.reversalK, at10.reversalK);
    EXPECT_EQ(mem.direction, 1);
    EXPECT_NEAR(kesBendAdvance(law, mem, 10.5), kesMomentOnBranch(law, at10, 10.5), 1e-12) << "the old branch goes on";
    EXPECT_LT(tentative, kesMomentOnBranch(law, at10, 10.0 - 0.9 * law.reversal)) << "behind the extreme: the reversal's branch";
    const double committed = kesBendAdvance(law, mem, 10.5 - 1.1 * law.reversal);
    EXPECT_EQ(mem.direction, -1);
    EXPECT_FLOAT_EQ(mem.reversalK, 10.5f);
    EXPECT_NEAR(committed, kesMomentOnBranch(law, mem, 10.5 - 1.1 * law.reversal), 1e-12);
}

// The dihedral angle's gradient (Bridson et al. 2003) against finite differences; flat is 0.
TEST(Kes, DihedralAngleAndItsGradient) {
    double theta = 1;
    Vec3d g[4];
    ASSERT_TRUE(dihedralAngle(Vec3(0.5f, 1, 0), Vec3(0.5f, -1, 0), Vec3(0, 0, 0), Vec3(1, 0, 0), theta, g));
    EXPECT_NEAR(theta, 0.0, 1e-12);
    Vec3 x[4] = {Vec3(0.33f, 0.9f, 0.25f), Vec3(0.61f, -1.05f, 0.42f), Vec3(0.02f, -0.04f, 0.01f), Vec3(1.03f, 0.1f, -0.05f)};
    ASSERT_TRUE(dihedralAngle(x[0], x[1], x[2], x[3], theta, g));
    EXPECT_GT(std::abs(theta), 0.3);
    Vec3d sum = Vec3d::Zero();
    for (int i = 0; i < 4; ++i) {
        sum += g[i];
        for (int k = 0; k < 3; ++k) {
            const float h = 1e-3f;
            Vec3 y[4] = {x[0], x[1], x[2], x[3]};
            double tp = 0, tm = 0;
            Vec3d unused[4];
            y[i][k] += h;
            dihedralAngle(y[0], y[1], y[2], y[3], tp, unused);
            y[i][k] -= 2 * h;
            dihedralAngle(y[0], y[1], y[2], y[3], tm, unused);
            EXPECT_NEAR(g[i][k], (tp - tm) / (2 * h), 2e-3) << "corner " << i << " axis " << k;
        }
    }
    EXPECT_NEAR(sum.norm(), 0.0, 1e-9) << "the gradients sum to zero (no net force)";
}

namespace {

// A strip W x H bent about an axis along its width into a cylinder of curvature K (the top edge
// fixed, tangent down), K = Km sin(2 pi i / n) for two cycles. Returns the work the material's
// bending forces do over the second cycle (trapezoid rule) and the sum of |work| over it; `loop`
// receives the moment-curvature loop area of the middle hinge row.
struct Bent {
    double work = 0, absWork = 0, hingeLoop = 0;
};
Bent bendBackAndForth(MaterialModel model, int nx, int ny, double W, double H, double Km) {
    Result<Cloth> built = buildCloth(makeGridMesh(nx, ny, W, H), 0.23f);
    EXPECT_TRUE(built.ok());
    Cloth c = std::move(built.value);
    MaterialSettings m;
    m.model = model;
    double top = -1e30;
    for (const Vec3d& r : c.rest) top = std::max(top, r.y());
    auto place = [&](double K) {
        for (Index p = 0; p < c.particleCount(); ++p) {
            const double s = top - c.rest[p].y();
            const double y = std::abs(K) < 1e-12 ? s : std::sin(K * s) / K;
            const double z = std::abs(K) < 1e-12 ? 0.0 : (1 - std::cos(K * s)) / K;
            c.x[p] = Vec3(float(c.rest[p].x()), float(top - y), float(z));
        }
    };
    // The hinge nearest the middle whose edge runs across the strip (along x): it bends.
    Index probe = kNone;
    double best = 1e30;
    for (Index b = 0; b < c.bends.size(); ++b) {
        const Spring& e = c.springs[c.bendEdge[b]];
        if (std::abs(c.rest[e.a].y() - c.rest[e.b].y()) > 1e-9) continue;
        const double d = std::abs(c.rest[e.a].y() - (top - H / 2)) + std::abs(0.5 * (c.rest[e.a].x() + c.rest[e.b].x()));
        if (d < best) best = d, probe = b;
    }
    EXPECT_NE(probe, kNone);
    std::vector<BendMemory> memory;
    std::vector<Vec3d> f(c.particleCount()), fLast;
    std::vector<Vec3> xLast;
    std::vector<double> moments;
    Bent out;
    const int n = 400;
    double lastK = 0, lastM = 0;
    for (int i = 0; i <= 2 * n; ++i) {
        const double K = Km * std::sin(2 * M_PI * i / n);
        place(K);
        std::fill(f.begin(), f.end(), Vec3d::Zero());
        materialBendForces(c, m, memory, f, &moments);
        if (i > n) {
            for (Index p = 0; p < c.particleCount(); ++p) {
                const double dw = 0.5 * (f[p] + fLast[p]).dot((c.x[p] - xLast[p]).cast<double>());
                out.work += dw;
                out.absWork += std::abs(dw);
            }
        }
        if (model == MaterialModel::Kes) {
            // moments holds (M, K) per hinge in bend order, skipping none on this flat-rest strip.
            const double M = moments[2 * probe], Kh = moments[2 * probe + 1];
            if (i > n) out.hingeLoop += 0.5 * (M + lastM) * (Kh - lastK);
            lastK = Kh, lastM = M;
        }
        fLast = f;
        xLast = c.x;
    }
    return out;
}

} // namespace

// Goal 4 of issue 16: a strip bent back and forth loses per cycle the loop's area times the bent
// area (every hinge across the strip: W x (H - h), h the row spacing), at 5 mm and at 2.5 mm; the
// middle hinge's own M-K loop has the law's area; the linear model loses nothing.
TEST(Kes, StripBentBackAndForthLosesTheLoopAreaTheLawPredicts) {
    const double W = 0.02, H = 0.05, Km = 50.0; // m, m, 1/m (0.5 cm^-1; K H stays below 2.5 rad)
    const KesLaw law = kesLawSI(MaterialSettings{});
    const double perArea = kesLoopEnergyPerArea(law, Km); // about 0.107 J/m^2
    for (const auto& [nx, ny] : {std::pair{5, 11}, std::pair{9, 21}}) {
        const double h = H / (ny - 1);
        const Bent kes = bendBackAndForth(MaterialModel::Kes, nx, ny, W, H, Km);
        EXPECT_NEAR(-kes.work, perArea * W * (H - h), 0.01 * perArea * W * (H - h)) << nx << " x " << ny;
        EXPECT_NEAR(kes.hingeLoop, perArea, 0.01 * perArea) << nx << " x " << ny;
        const Bent linear = bendBackAndForth(MaterialModel::Linear, nx, ny, W, H, Km);
        EXPECT_GT(linear.absWork, 1e-7) << "the linear strip's bend-shear springs do work";
        EXPECT_LT(std::abs(linear.work), 1e-3 * linear.absWork) << nx << " x " << ny << ": no loop for linear";
    }
}

TEST(Kes, BadModelOrCoefficientsAreRefusedByTheTable) {
    Settings s;
    EXPECT_EQ(setParamFromString(s, "material.model", "kes"), "");
    EXPECT_EQ(s.material.model, MaterialModel::Kes);
    EXPECT_EQ(setParamFromString(s, "material.model", "foo"),
              "parameter 'material.model': 'foo' is not one of: linear, kes");
    EXPECT_EQ(setParamFromString(s, "material.kes_t4", "-1"),
              "parameter 'material.kes_t4': -1 is outside the valid range [0, 10000] gf/cm per %^4");
    EXPECT_NE(setParamFromString(s, "material.kes_bend_alpha", "0"), "");
    EXPECT_EQ(s.material.kesT4, MaterialSettings{}.kesT4) << "a refused value changes nothing";
}

// The guard takes the law's largest tangent over the strains the limit lets a spring reach: a
// range of 10 % instead of 3 % asks for a step shorter by sqrt(T'(3 %) / T'(10 %)) (without the
// hinges and the damping, which add to both), and the swing stays finite with it; without the guard it explodes.
// Past the range the law goes on with its tangent there (kesTensionInRange).
TEST(Kes, GuardUsesTheLawsLargestTangent) {
    const KesLaw law0 = kesLawSI(MaterialSettings{});
    EXPECT_DOUBLE_EQ(kesTensionInRange(law0, 0.02, 0.03), kesTension(law0, 0.02));
    EXPECT_NEAR(kesTensionInRange(law0, -0.05, 0.03), -(kesTension(law0, 0.03) + 0.02 * kesTangent(law0, 0.03)), 1e-9);
    // Springs alone, undamped (damping shortens both steps by different fractions).
    const std::vector<std::string> springs = {"material.kes_bend_d=0", "material.kes_bend_d1=0", "material.stretch_damping=0"};
    World narrowSprings = scene("swing-vacuum", springs);
    std::vector<std::string> wider = springs;
    wider.push_back("limit.max_stretch=0.1");
    World wideSprings = scene("swing-vacuum", wider);
    World narrow = scene("swing-vacuum", {});
    World wide = scene("swing-vacuum", {"limit.max_stretch=0.1"});
    const KesLaw law = kesLawSI(narrow.settings.material);
    const double expected = std::sqrt(kesTangent(law, 0.03) / kesTangent(law, 0.10));
    const double ratio = stableStepEstimate(wideSprings.cloth, wideSprings.settings) /
                         stableStepEstimate(narrowSprings.cloth, narrowSprings.settings);
    EXPECT_NEAR(ratio, expected, 0.01 * expected);
    // The hinges make both steps shorter, the narrow one more (they are a larger share of its sum).
    EXPECT_LT(stableStepEstimate(narrow.cloth, narrow.settings), stableStepEstimate(narrowSprings.cloth, narrowSprings.settings));
    const double withHinges = stableStepEstimate(wide.cloth, wide.settings) / stableStepEstimate(narrow.cloth, narrow.settings);
    EXPECT_GT(withHinges, expected);
    EXPECT_LT(withHinges, 1.2 * expected);
    for (int f = 0; f < 20; ++f) narrow.step();
    EXPECT_TRUE(narrow.finite);
    EXPECT_GT(narrow.frameSubsteps, 500) << "the guard raised the sub-steps for the law's stiffness";
    EXPECT_LT(narrow.maxStrain, 0.03f);
    EXPECT_LT(narrow.maxSpeed, 2.f) << "a 0.1 m strip released 60 mm out";
    World unguarded = scene("swing-vacuum", {"time.stability_guard=0", "time.substeps=50"});
    for (int f = 0; f < 20 && unguarded.finite; ++f) unguarded.step();
    EXPECT_TRUE(!unguarded.finite || unguarded.maxSpeed > 10.f) << "50 sub-steps a frame are too few for the law";
}

// The hinges' memory is state: a saved and loaded swing continues bit for bit, a checkpoint restores
// it, and a world that forgets it steps differently (so the comparisons above can fail).
TEST(Kes, HingeMemorySurvivesSaveLoadAndRewind) {
    World w = scene("swing-vacuum", {});
    for (int f = 0; f < 6; ++f) w.step();
    ASSERT_EQ(w.cloth.bendMemory.size(), w.cloth.bends.size());
    std::string bytes;
    ASSERT_EQ(serializeWorld(w, bytes), "");
    Result<World> copy = parseWorld(bytes, "kes.ctw");
    ASSERT_EQ(copy.error, "");
    History history;
    history.record(w);
    const uint64_t atSave = stateHash(w);
    World forgetful = copy.value;
    forgetful.cloth.bendMemory.clear();
    for (int f = 0; f < 4; ++f) w.step(), copy.value.step(), forgetful.step();
    EXPECT_EQ(hashHex(stateHash(copy.value)), hashHex(stateHash(w)));
    EXPECT_NE(hashHex(stateHash(forgetful)), hashHex(stateHash(w))) << "the memory decides the future";
    World r = scene("curtain", {"cloth.resolution_x=4", "cloth.resolution_y=4"});
    history.at(0).restore(r);
    EXPECT_EQ(hashHex(stateHash(r)), hashHex(atSave));
    for (int f = 0; f < 4; ++f) r.step();
    EXPECT_EQ(hashHex(stateHash(r)), hashHex(stateHash(w)));
}

// Tearing keeps working with the law: the threshold is a strain, the memory follows the bends
// through every split (validateCloth checks the lengths), and the torn cloth stays finite.
TEST(Kes, TensionTearsWithTheKesLaw) {
    World w = scene("tension", {"material.model=kes", "cloth.resolution_x=16", "cloth.resolution_y=12",
                                "tear.validate=1"});
    for (int f = 0; f < 90; ++f) w.step();
    EXPECT_TRUE(w.finite) << w.nonFiniteWhere;
    EXPECT_GT(w.tearLog.total(), 0u);
    EXPECT_EQ(w.tearLog.validationError, "");
    EXPECT_EQ(w.cloth.bendMemory.size(), w.cloth.bends.size());
}

namespace {

// The free end's mean drop below its rest place (m), along the strip's up direction.
double freeEndDrop(const World& w) {
    const MeshFrame f = meshFrame(w.cloth.rest);
    double drop = 0;
    int n = 0;
    for (Index p = 0; p < w.cloth.particleCount(); ++p)
        if (f.v(w.cloth.rest[p]) <= f.minV + 1e-9) drop += f.up.dot(w.cloth.rest[p] - w.cloth.x[p].cast<double>()), ++n;
    return drop / n;
}

// A strip of free length L hanging under its own weight: at s above its free end a unit width
// carries rho g s, so its strain solves T(e) = rho g s and its end drops int_0^L e(s) ds (midpoint
// rule, e by bisection: T grows with e).
double hangingDrop(const KesLaw& law, double rhoG, double length) {
    const int n = 4000;
    double drop = 0;
    for (int i = 0; i < n; ++i) {
        const double load = rhoG * (i + 0.5) * length / n;
        double lo = 0, hi = 1;
        for (int k = 0; k < 100; ++k) (kesTension(law, 0.5 * (lo + hi)) < load ? lo : hi) = 0.5 * (lo + hi);
        drop += 0.5 * (lo + hi) * length / n;
    }
    return drop;
}

} // namespace

// Implicit Euler with the law's Jacobian (implicit_euler.h: the tensile tangent T'(e) weight along
// each spring and F / l across it, each hinge's dtau/dtheta): the vacuum strip hanging from its clamp
// settles where the tensile law puts it. Its end drops 0.1011 mm by the law (T(e) = rho g s, 95 mm
// free); the mesh carries the load on its diagonals too, as the linear model's does, and drops 3.2 %
// less (0.0979 mm at 5 and at 2.5 mm, the same within 0.05 %). The explicit guard at 5 mm (1852
// sub-steps a frame) settles on the same drop (an equilibrium does not depend on the integrator): so
// does implicit Euler with one sub-step a frame (dt = 16.7 ms, 800 x the explicit step). Before the
// Jacobian the law entered implicit Euler as an explicit force, capped by the guard for a step that
// long: the end dropped 1.87 mm (19 x) and the swing below reached the length limit (3.2 %).
TEST(Kes, ImplicitEulerHangsAtTheLawsStaticElongation) {
    const KesLaw law = kesLawSI(MaterialSettings{});
    const double predicted = hangingDrop(law, 0.23 * 9.81, 0.095);
    EXPECT_NEAR(predicted, 1.011e-4, 1e-7);
    auto hang = [](std::vector<std::string> sets, int frames) {
        sets.push_back("impulse.spin=0"); // hanging at rest from the clamp
        World w = scene("impulse-rotation", sets);
        for (int f = 0; f < frames && w.finite; ++f) w.step();
        EXPECT_TRUE(w.finite) << w.nonFiniteWhere;
        EXPECT_LT(w.maxSpeed, 1e-3f) << "settled (the stretch modes, ~1e3 rad/s: under 1e-6 m)";
        return freeEndDrop(w);
    };
    const std::vector<std::string> fine = {"cloth.resolution_x=9", "cloth.resolution_y=41"};
    const double coarse = hang({"time.integrator=implicit-euler"}, 60);
    std::vector<std::string> fineImplicit = fine;
    fineImplicit.push_back("time.integrator=implicit-euler");
    const double fineDrop = hang(fineImplicit, 60);
    EXPECT_NEAR(coarse, predicted, 0.05 * predicted) << "the law's drop, within the mesh's share on its diagonals";
    EXPECT_LT(coarse, predicted) << "the diagonals carry some of the load";
    EXPECT_NEAR(fineDrop, coarse, 0.005 * coarse) << "5 mm and 2.5 mm";
    const double oneSubstep = hang({"time.integrator=implicit-euler", "time.substeps=1"}, 60);
    EXPECT_NEAR(oneSubstep, coarse, 0.005 * coarse) << "dt = 16.7 ms";
    const double explicitGuard = hang({"time.integrator=semi-implicit-euler"}, 40);
    EXPECT_NEAR(explicitGuard, coarse, 0.005 * coarse) << "the explicit guard's equilibrium";
}

// The free end's mean offset along the strip's normal (m): the swing's coordinate.
double freeEndOffset(const World& w) {
    const MeshFrame f = meshFrame(w.cloth.rest);
    double offset = 0;
    int n = 0;
    for (Index p = 0; p < w.cloth.particleCount(); ++p)
        if (f.v(w.cloth.rest[p]) <= f.minV + 1e-9) offset += f.normal.dot(w.cloth.x[p].cast<double>() - w.cloth.rest[p]), ++n;
    return offset / n;
}

// Large steps: the vacuum swing (released 60 mm out, so every hinge bends and reverses) with
// implicit Euler at 10 and at 1 sub-step a frame stays finite with strains far below the limit
// (3 %, where the springs went before the Jacobian), and at 10 it still swings as the explicit
// integrators do (semi-implicit Euler with the guard: period 0.414 s, the amplitude halved by
// 1.31 s): the period within 3 % of that (0.422 s), and the hysteresis damps it (the last second's
// swing under half the first). With the branch's slope in the hinges' Jacobian instead of the
// law's largest (HingeTangent, kes.h) the hinges zig-zagged at 10 sub-steps: the period of
// D1 = 0 (0.50 s), no decay.
TEST(Kes, ImplicitEulerSwingsAtLargeSteps) {
    for (const char* substeps : {"10", "1"}) {
        World w = scene("swing-vacuum", {"time.integrator=implicit-euler", std::string("time.substeps=") + substeps});
        std::vector<double> offset, peaks; // per frame; times of the maxima
        float fastest = 0;
        for (int f = 0; f < 300 && w.finite; ++f) {
            w.step();
            fastest = std::max(fastest, w.maxSpeed);
            offset.push_back(freeEndOffset(w));
            const size_t k = offset.size();
            if (k >= 3 && offset[k - 2] > offset[k - 3] && offset[k - 2] >= offset[k - 1])
                peaks.push_back((k - 1) * double(w.settings.time.frameDt)); // the frame before
        }
        EXPECT_TRUE(w.finite) << substeps << ": " << w.nonFiniteWhere;
        EXPECT_LT(fastest, 2.f) << substeps << ": a swing from 60 mm";
        EXPECT_LT(w.maxStrain, 0.01f) << substeps;
        if (std::string(substeps) != "10") continue;
        // Over the first three periods, while the swing is large (the bench's period counts only
        // half swings over 6 mm; as the swing dies out the steep start of each branch shortens it:
        // 0.37 s in the last seconds here).
        ASSERT_GE(peaks.size(), 4u);
        const double period = (peaks[3] - peaks[0]) / 3.0;
        EXPECT_NEAR(period, 0.414, 0.03 * 0.414);
        auto range = [&](size_t from, size_t to) {
            const auto [lo, hi] = std::minmax_element(offset.begin() + from, offset.begin() + to);
            return *hi - *lo;
        };
        EXPECT_LT(range(offset.size() - 60, offset.size()), 0.5 * range(0, 30)) << "the hysteresis damps the swing";
    }
}

// The hinge's linearization (HingeTangent, for implicit Euler) against a finite difference: at a
// flat hinge (tau = 0, so the dropped term tau d^2 theta / dx^2 is zero) moving its corners by h u
// turns it by h g . u and its torque by (dtau/dtheta) h g . u, dtau/dtheta = (D + alpha D1) w / L on
// the virgin curve; the forces are then -tau g.
TEST(Kes, HingeTangentIsTheForcesDerivative) {
    World w = scene("swing-vacuum", {"swing.offset=0"});
    const Cloth& c = w.cloth;
    const KesLaw law = kesLawSI(w.settings.material);
    const Index b = c.bends.size() / 2;
    const HingeGeometry h = hingeOf(c, b);
    const Index corners[4] = {h.c, h.d, h.a, h.e};
    std::vector<HingeTangent> tangents;
    std::vector<BendMemory> memory;
    std::vector<Vec3d> f0(c.particleCount(), Vec3d::Zero());
    HingeStep step;
    step.tangents = &tangents;
    materialBendForces(c, w.settings.material, memory, f0, nullptr, step);
    ASSERT_EQ(tangents.size(), c.bends.size());
    const HingeTangent& t = tangents[b];
    EXPECT_NEAR(t.stiffness, kesMaxBendSlope(law) * h.width / h.length, 1e-9 * t.stiffness);
    // A move of all four corners (so the angle changes) along the mesh's normal, different amounts.
    const double amount[4] = {1.0, -0.5, 0.25, 0.75}, step_h = 1e-6;
    const Vec3d normal = meshFrame(c.rest).normal;
    double rate = 0;
    for (int i = 0; i < 4; ++i) rate += t.grad[i].dot(amount[i] * normal);
    ASSERT_GT(std::abs(rate), 1.0) << "the move bends the hinge";
    Cloth moved = c;
    for (int i = 0; i < 4; ++i) moved.x[corners[i]] += (step_h * amount[i] * normal).cast<float>();
    // Hinge b's own torque after the move (its neighbours bend too: their forces are not its).
    std::vector<double> moments;
    std::vector<BendMemory> memory1;
    std::vector<Vec3d> f1(c.particleCount(), Vec3d::Zero());
    materialBendForces(moved, w.settings.material, memory1, f1, &moments);
    const double tau = moments[2 * b] * h.width;
    const double expectedTau = t.stiffness * rate * step_h;
    EXPECT_NEAR(tau, expectedTau, 0.01 * std::abs(expectedTau)) << "dtau = dtau/dtheta dtheta";
}

// Forward Euler's Rayleigh damping of the law (kesRayleighTime, kes.h), on one mode: a triangle with
// A = (-1, 0) and B = (1, 0) pinned and C = (0, 1) free (no gravity, air, damping, limit or guard;
// one triangle has no hinge), C displaced by 1 mm across A-B. A law with a linear term only,
// T = c1 e, makes each spring k = c1 weight (weight 1/2) and C swing at omega^2 = k / m_C
// (tests/test_stability.cpp, GuardKeepsTheMaterialWithinItsBudgetAndCapsEachSpringWhileABallIsNear). Forward Euler
// multiplies that mode's amplitude by sqrt(1 - g dt + (omega dt)^2) a step: the undamped method
// (the linear model with the same k) grows it by sqrt(1 + (omega dt)^2); the law with C = 2 dt K
// (g = 2 dt omega^2) shrinks it by sqrt(1 - (omega dt)^2). Here omega dt = 0.1: 1.00499 against
// 0.99499 a step, over 400 steps (six periods) x 7.3 against x 0.13.
double amplitudeRatioPerStep(const char* model) {
    World w;
    w.settings = test::quietSettings();
    Settings& s = w.settings;
    s.time.integrator = Integrator::ForwardEuler;
    s.time.stabilityGuard = false;
    s.time.frameDt = 0.01f;
    s.time.substeps = 10; // dt = 1 ms
    const double mC = double(s.material.density) / 3.0, k = 1e4 * mC; // omega^2 = k / m_C = 1e4 / s^2
    s.material.stretchStiffness = float(k / 0.5);                      // linear: S weight = k
    s.material.kesT1 = float(k / 0.5 / (kGramForce / kCentimetre * 100.0)); // kes: c1 weight = k
    s.material.kesT2 = s.material.kesT3 = s.material.kesT4 = 0.f;
    s.material.kesBendD = s.material.kesBendD1 = 0.f;
    EXPECT_EQ(setParamFromString(s, "material.model", model), "");
    EXPECT_EQ(test::buildOscillator(w), "");
    std::vector<std::pair<int, double>> peaks; // (step, u) at the maxima of |u|
    double u1 = 1e-3, u2 = 1e-3;
    for (int n = 1; n <= 400; ++n) {
        w.substep();
        const double u = double(w.cloth.x[2].y()) - 1.0;
        if (n >= 2 && std::abs(u1) > std::abs(u2) && std::abs(u1) >= std::abs(u)) peaks.emplace_back(n - 1, std::abs(u1));
        u2 = u1, u1 = u;
    }
    EXPECT_TRUE(w.cloth.x[2].allFinite());
    EXPECT_GE(peaks.size(), 8u) << model;
    if (peaks.size() < 2) return 0;
    const auto [n0, a0] = peaks.front();
    const auto [n1, a1] = peaks.back();
    return std::pow(a1 / a0, 1.0 / double(n1 - n0));
}

TEST(Kes, ForwardEulerDampsTheLawAtTheRateItsRayleighTermGives) {
    const double omegaDt2 = 0.01; // (omega dt)^2
    const double linear = amplitudeRatioPerStep("linear"), kes = amplitudeRatioPerStep("kes");
    EXPECT_NEAR(std::log(linear), 0.5 * std::log(1 + omegaDt2), 0.01 * 0.5 * omegaDt2) << "the undamped method grows";
    EXPECT_NEAR(std::log(kes), 0.5 * std::log(1 - omegaDt2), 0.01 * 0.5 * omegaDt2) << "the law's Rayleigh damping";
}
