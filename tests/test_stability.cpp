// Stability: the guard's estimate of the stable step against a measured blow-up, the guard's
// sub-step choice, and randomized parameter sets from the panel's safe ranges that must never
// produce a non-finite value with balls, wind, drags and tearing.
//
// Section index:
//   [ESTIMATE]   stableStepEstimate: stable below it, the estimate within a factor of the truth
//   [GUARD]      sub-steps chosen by the guard
//   [DAMPING]    time.damping: the oscillator's decay, stable past the explicit bound, the guard's
//                step from the stiffness alone, auto where the explicit damping would soften
//   [RANDOM]     randomized safe parameter sets, 5 s each (the kes law: 1.5 s)
#include "clothtear/params.h"
#include "clothtear/random.h"
#include "clothtear/scenes.h"
#include "clothtear/tear.h"
#include "clothtear/world.h"
#include "quiet_settings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace clothtear;

namespace {

// ========================================================================================= [ESTIMATE]

// Runs the swing (a large motion that excites every mode) for 1 s at sub-step dt with the guard
// and the limit off; true if it stays finite with strain below 10.
bool stableAt(double dt, float stiffness) {
    World w;
    EXPECT_EQ(loadScene(w, "swing",
                        std::vector<std::string>{"cloth.resolution_x=12", "cloth.resolution_y=12",
                                                 "limit.enabled=false", "time.stability_guard=false",
                                                 "time.substeps=1", "time.frame_dt=" + std::to_string(dt),
                                                 "material.stretch_stiffness=" + std::to_string(stiffness)}),
              "");
    const int frames = int(std::ceil(1.0 / dt));
    for (int f = 0; f < frames && w.finite; ++f) {
        w.step();
        if (w.maxStrain > 10.f)
            return false;
    }
    return w.finite;
}

// Semi-implicit Euler is stable at the estimate (Gershgorin is a bound, so the estimate is on the
// safe side) and unstable at 4x the estimate (so it is not uselessly small): the real limit lies
// in between. For a grid, the measured limit is about 1.5x the estimate (bench/README.md).
TEST(Stability, EstimateIsSafeAndWithinAFactorOfFourOfTheBlowUp) {
    for (float stiffness : {60.f, 2000.f}) {
        World w;
        ASSERT_EQ(
            loadScene(w, "swing",
                      std::vector<std::string>{"cloth.resolution_x=12", "cloth.resolution_y=12",
                                               "material.stretch_stiffness=" + std::to_string(stiffness)}),
            "");
        const double estimate = stableStepEstimate(w.cloth, w.settings);
        ASSERT_TRUE(std::isfinite(estimate));
        EXPECT_TRUE(stableAt(estimate, stiffness)) << "S=" << stiffness << " estimate " << estimate << " s";
        EXPECT_FALSE(stableAt(4 * estimate, stiffness))
            << "S=" << stiffness << " estimate " << estimate << " s";
    }
}

// ============================================================================================ [GUARD]

// The guard raises sub-steps to frameDt / estimate when time.max_substeps allows, never lowers
// them, and leaves the reference integrators alone.
TEST(Stability, GuardPicksTheSubstepsTheEstimateNeeds) {
    World w;
    ASSERT_EQ(loadScene(w, "curtain",
                        std::vector<std::string>{"cloth.resolution_x=64", "cloth.resolution_y=64",
                                                 "time.max_substeps=200"}),
              "");
    // The guard's step: stable (Gershgorin) and short enough that no spring of the heaviest 99%
    // of the mass needs the per-spring cap, so it is at most the stable step estimate.
    const double estimate = guardStepEstimate(w.cloth, w.settings, kGuardLightMass);
    EXPECT_LE(estimate, stableStepEstimate(w.cloth, w.settings) * (1 + 1e-12));
    const int need = int(std::ceil(double(w.settings.time.frameDt) / estimate));
    ASSERT_GT(need, w.settings.time.substeps) << "64x64 at the default material needs more than 10";
    EXPECT_EQ(w.guardSubsteps(), need);
    w.step();
    EXPECT_EQ(w.frameSubsteps, need);
    EXPECT_EQ(w.profile.substeps, uint64_t(need));
    w.settings.time.maxSubsteps = 12;
    EXPECT_EQ(w.guardSubsteps(), 12) << "capped at time.max_substeps (springs are capped beyond)";
    w.settings.time.maxSubsteps = 5;
    EXPECT_EQ(w.guardSubsteps(), 10) << "never fewer than time.substeps";
    w.settings.time.maxSubsteps = 200;
    w.settings.time.stabilityGuard = false;
    EXPECT_EQ(w.guardSubsteps(), 10);
    w.settings.time.stabilityGuard = true;
    w.settings.time.integrator = Integrator::ImplicitEuler;
    EXPECT_EQ(w.guardSubsteps(), 10);
}

// The guard's step skips the lightest particles by mass, however many they are by count: a third of
// the particles made 10^4 times lighter (each needs a step 10^2-10^4 x shorter; together 0.003 % of
// the mass) leave the step of the rest. The estimate orders only the shortest steps, a few per cent of
// the particles at first, and takes more when their mass is not enough: here it must look past
// 1,365 light ones. With no light mass allowed it is their step.
TEST(Stability, GuardStepSkipsLightParticlesHoweverMany) {
    World w;
    ASSERT_EQ(loadScene(w, "curtain", std::vector<std::string>{"cloth.resolution_x=64", "cloth.resolution_y=64"}), "");
    const double heavy = guardStepEstimate(w.cloth, w.settings, kGuardLightMass);
    size_t light = 0;
    double lightMass = 0, mass = 0;
    for (Index p = 0; p < w.cloth.particleCount(); ++p) {
        if (w.cloth.invMass[p] == 0.f) continue;
        if (p % 3 == 0) {
            w.cloth.invMass[p] *= 1e4f;
            ++light;
            lightMass += 1.0 / w.cloth.invMass[p];
        }
        mass += 1.0 / w.cloth.invMass[p];
    }
    ASSERT_GT(light, 1300u);
    ASSERT_LT(lightMass, 1e-3 * mass);
    // The heavy particles' springs and masses are as before; the quantile of their steps is too,
    // unless the mass taken out moves it across a change of step: checked with two fractions.
    EXPECT_EQ(guardStepEstimate(w.cloth, w.settings, kGuardLightMass), heavy);
    World uniform;
    ASSERT_EQ(loadScene(uniform, "curtain", std::vector<std::string>{"cloth.resolution_x=64", "cloth.resolution_y=64"}), "");
    EXPECT_EQ(guardStepEstimate(w.cloth, w.settings, 0.2), guardStepEstimate(uniform.cloth, uniform.settings, 0.2));
    // No light mass allowed: the lightest particles' step, between 10^2 (stiffness: dt^2 w) and 10^4
    // (damping: dt w) times shorter.
    const double lightest = guardStepEstimate(w.cloth, w.settings, 0.0);
    EXPECT_LT(lightest, heavy / 99);
    EXPECT_GT(lightest, heavy / 1.0001e4);
}

// The guard's caps seen in the period of an oscillator: a triangle with A = (-1, 0) and B = (1, 0)
// pinned and C = (0, 1) free (no gravity, air or damping), C displaced by 1 mm. C swings on the two
// springs AC and BC: u'' = -omega^2 u with omega^2 = 2 k (h / L)^2 / m = k w with w = 1/m_C,
// (h / L)^2 = 1/2. Semi-implicit Euler swings at the discrete cos(Omega dt) = 1 - (omega dt)^2 / 2,
// a period of 2 pi / Omega. One sub-step a frame of 1 ms, so the guard caps and never adds steps.
enum class Guard { Off, On, OnWithABallNear };
double oscillatorPeriodInSteps(float stiffness, Guard guard) {
    World w;
    w.settings = test::quietSettings();
    Settings& s = w.settings;
    s.material.stretchStiffness = stiffness;
    s.time.frameDt = 1e-3f;
    s.time.substeps = 1;
    s.time.maxSubsteps = 1;
    s.time.stabilityGuard = guard != Guard::Off;
    s.sleep.enabled = false;
    EXPECT_EQ(test::buildOscillator(w), "");
    // An immovable ball 1 m below the cloth's edge A-B: within the guard's reach (its radius, a mean
    // rest length and a frame's travel), never touching C.
    if (guard == Guard::OnWithABallNear) w.balls.push_back(Ball{Vec3(0.f, -1.f, 0.f), Vec3::Zero(), 0.1f, 0.f});
    std::vector<double> crossings; // sub-steps at which u changes sign, linearly interpolated
    double uPrev = 1e-3;
    for (int n = 1; n <= 400; ++n) {
        w.step();
        const double u = double(w.cloth.x[2].y()) - 1.0;
        if ((uPrev > 0) != (u > 0))
            crossings.push_back(n - 1 + uPrev / (uPrev - u));
        uPrev = u;
    }
    EXPECT_TRUE(w.cloth.x[2].allFinite());
    EXPECT_GE(crossings.size(), 20u);
    return crossings.size() < 2 ? 0 : 2.0 * (crossings.back() - crossings.front()) / double(crossings.size() - 1);
}

// k w dt^2 of one spring as asked: S x weight (area 1 / L^2 = 1/2) x 3 / (rho h) x dt^2, and C's
// Gershgorin load w_C sum(k) dt^2 / 2 is the same number (two springs).
// - 1e5 N/m asks 0.75, within the guard's budget (0.9): the guard keeps the material as set, a
//   period of 7.0 sub-steps as without it.
// - 2e5 N/m asks 1.5 (stable, the method needs omega dt < 2, but past the budget): the guard scales
//   C's springs to the budget, (omega dt)^2 = 0.9, 6.6 sub-steps.
// - With a ball near (or a hand moving), each spring is capped alone at k w dt^2 = 1/3: 10.7.
TEST(Stability, GuardKeepsTheMaterialWithinItsBudgetAndCapsEachSpringWhileABallIsNear) {
    auto discretePeriod = [](double omegaDt2) { return 2.0 * M_PI / std::acos(1.0 - omegaDt2 / 2.0); };
    auto asked = [](double stiffness) { return stiffness * 0.5 * 3.0 / (0.2 * 1.0) * 1e-6; };
    ASSERT_NEAR(asked(1e5), 0.75, 1e-12);
    for (const Guard g : {Guard::Off, Guard::On})
        EXPECT_NEAR(oscillatorPeriodInSteps(1e5f, g), discretePeriod(0.75), 0.01 * discretePeriod(0.75));
    EXPECT_NEAR(oscillatorPeriodInSteps(2e5f, Guard::Off), discretePeriod(asked(2e5)), 0.01 * discretePeriod(1.5));
    EXPECT_NEAR(oscillatorPeriodInSteps(2e5f, Guard::On), discretePeriod(0.9),
                0.01 * discretePeriod(0.9));
    EXPECT_NEAR(oscillatorPeriodInSteps(1e5f, Guard::OnWithABallNear), discretePeriod(1.0 / 3.0),
                0.01 * discretePeriod(1.0 / 3.0));
}

// =========================================================================================== [RANDOM]

// Every parameter drawn uniformly from its safe range (the panel's default slider span), bools and
// enums at random, except:
//  - cloth.resolution_x/y in [4, 20] and time.substeps below a budget of sub-steps per run (20000
//    explicit, 6000 XPBD, 1500 implicit Euler): small cloths keep the whole test near a minute;
//  - time.stability_guard on (the claim under test: the guard keeps the safe ranges stable);
//  - cloth.mesh grid or irregular (obj needs a file); validateCloth after each run;
//  - the geometry of the scene (pull/tension/ball parameters) is unused: interactions come from the
//    script below.
// Script: two balls thrown at the cloth (radius, speed and mass from their safe ranges), a drag
// (a pinned, driven particle) for one second then released, wind on for the whole run.
// Each parameter's value comes from its own stream (the run's seed and the parameter's name), so a row
// added to the table leaves every other draw as it was.
uint64_t nameHash(const char* name) {
    uint64_t h = 1469598103934665603ull; // FNV-1a
    for (; *name; ++name) h = (h ^ uint8_t(*name)) * 1099511628211ull;
    return h;
}

Settings randomSafeSettings(Rng& runRng) {
    Settings s;
    const uint64_t runSeed = runRng.next();
    for (const ParamInfo& p : allParams()) {
        Rng rng(runSeed ^ nameHash(p.name));
        double v = 0;
        switch (p.type) {
        case ParamType::Float:
            v = rng.uniform(p.safeMin, p.safeMax);
            break;
        case ParamType::Int:
            v = std::floor(rng.uniform(p.safeMin, p.safeMax + 1));
            break;
        case ParamType::Bool:
            v = rng.uniform() < 0.5;
            break;
        case ParamType::Enum: {
            int n = 0;
            while (p.enumNames[n])
                ++n;
            v = rng.below(uint32_t(n));
            break;
        }
        }
        setParamUnchecked(s, p, v);
    }
    Rng rng(runSeed);
    s.cloth.resolutionX = 4 + int(rng.below(17));
    s.cloth.resolutionY = 4 + int(rng.below(17));
    s.cloth.mesh = rng.uniform() < 0.5 ? MeshType::Grid : MeshType::Irregular;
    s.time.stabilityGuard = true;
    s.tear.validate = false; // validateCloth runs at the end of each run (every tear: minutes in a cascade)
    s.tear.enabled = true;
    s.wind.enabled = true;
    // The linear material here; the kes law's random sets are RandomSafeKesParameterSetsStayFinite's.
    s.material.model = MaterialModel::Linear;
    return s;
}

// Every parameter as key=value (for a failure message that can be replayed with --set).
std::string allAssignments(const Settings& s) {
    std::string o;
    for (const ParamInfo& p : allParams())
        o += std::string(" --set ") + p.name + "=" + formatParamValue(s, p);
    return o;
}

// One randomized run (the script above) of `settings` as drawn; tore / cascades count its outcome.
void runRandomSet(Rng& rng, Settings settings, int run, int& tore, int& cascades, double seconds = 5.0) {
    World w;
    w.settings = settings;
    const Integrator integ = w.settings.time.integrator;
    const double budget = integ == Integrator::ImplicitEuler ? 1500
                          : integ == Integrator::Xpbd        ? 6000
                                                             : 20000;
    const int frames = int(std::ceil(seconds / w.settings.time.frameDt));
    w.settings.time.substeps = std::clamp(w.settings.time.substeps, 1, std::max(1, int(budget / frames)));
    w.settings.time.maxSubsteps = std::max(w.settings.time.maxSubsteps, 1);
    ASSERT_EQ(w.rebuild(), "") << "run " << run;
    const Settings& s = w.settings;
    std::string what =
        "run " + std::to_string(run) + ": " + formatParamValue(s, *findParam("material.model")) + " " +
        formatParamValue(s, *findParam("time.integrator")) + " " + std::to_string(s.cloth.resolutionX) + "x" +
        std::to_string(s.cloth.resolutionY) + " frame_dt " + std::to_string(s.time.frameDt) + " substeps " +
        std::to_string(s.time.substeps) + " S " + std::to_string(s.material.stretchStiffness) + " rho " +
        std::to_string(s.material.density) + " pin " + formatParamValue(s, *findParam("cloth.pin"));
    // Centre of the cloth, to aim at.
    Vec3 centre = Vec3::Zero();
    for (const Vec3& x : w.cloth.x)
        centre += x;
    centre /= float(w.cloth.particleCount());
    const Index grabbed = Index(rng.below(uint32_t(w.cloth.particleCount())));
    const size_t initialParticles = w.cloth.particleCount();
    const Vec3 dragVelocity =
        s.scene.pullSpeed * Vec3(float(rng.uniform(-1, 1)), float(rng.uniform(-1, 1)), float(rng.uniform(-1, 1)));
    for (int f = 0; f < frames; ++f) {
        const double t = w.time;
        if (f == frames / 5 || f == frames / 2) { // throw a ball from 1.5 m in front of the cloth
            Ball b;
            b.radius = s.scene.ballRadius;
            b.mass = s.scene.ballMass;
            b.x = centre + Vec3(0.f, 0.f, 1.5f + b.radius);
            b.v = Vec3(0.f, 0.f, -s.scene.ballSpeed);
            w.balls.push_back(b);
        }
        if (f == frames / 10) { // grab
            w.cloth.setPinned(grabbed, true);
            w.drivers.push_back(Driver{{grabbed}, dragVelocity});
        }
        if (t >= 1.0 + seconds / 10 && !w.drivers.empty()) { // release after a second
            for (Index p : w.drivers.front().particles)
                w.cloth.setPinned(p, false);
            w.drivers.clear();
        }
        w.step();
        if (w.cloth.particleCount() > 20 * initialParticles) { // a tear cascade: finite so far, stop here
            ++cascades;
            testing::Test::RecordProperty("cascade_run" + std::to_string(run), what);
            break;
        }
        ASSERT_TRUE(w.finite) << what << ": non-finite at frame " << f << " (" << w.nonFiniteWhere << ")\n"
                              << allAssignments(s);
    }
    for (const Vec3& x : w.cloth.x)
        ASSERT_TRUE(x.allFinite()) << what;
    EXPECT_EQ(w.tearLog.validationError, "") << what;
    EXPECT_EQ(validateCloth(w.cloth), "") << what;
    tore += w.tearLog.total() > 0;
    testing::Test::RecordProperty("run" + std::to_string(run), what + " tears " + std::to_string(w.tearLog.total()));
}

TEST(Stability, RandomSafeParameterSetsStayFinite) {
    Rng rng(20240605);
    const int sets = 16;
    int tore = 0, cascades = 0;
    for (int run = 0; run < sets; ++run) {
        ASSERT_NO_FATAL_FAILURE(runRandomSet(rng, randomSafeSettings(rng), run, tore, cascades));
    }
    EXPECT_GT(tore, 0) << "some of the runs must tear, or tearing is not being tested";
    // A run whose cloth tears into more than 20x its particles is stopped there (finite so far):
    // such cascades happen at extreme corners of the safe ranges (an 18 m x 0.11 m strip at tear
    // threshold 2.7 without the length limit shreds into slivers). Counted, not failed: the claim
    // tested here is finiteness. Reported in the test's XML properties.
    RecordProperty("cascades", std::to_string(cascades));
}

// The same with material.model = kes (issue 16): the same draws (so every integrator, as drawn),
// the law's coefficients from their safe ranges too (up to 12 x Tagawa's, and t1, t3 which Tagawa's
// fit leaves at 0: the tangent at 30 % strain reaches 1e6-1e7 N/m, 1e4-1e5 x the linear default).
// Forward Euler went non-finite here before its Rayleigh damping of the law (kesRayleighTime,
// kes.h; docs/kes-material.md, "Forward Euler"): run 13 (forward Euler, the cloth below a 7.6 m
// ground) within the first frame, the law's undamped modes growing from the ground's push. To keep
// the test near the linear one's time (the guard takes up to time.max_substeps with this law, and
// at 5 s and up to 20 x 20 two runs that shred the cloth took 20 and 60 s): 1.5 s a run and grids of
// 4 to 12 (the drawn 4 to 20 halved); at 5 s the same runs stay finite too (14 s).
TEST(Stability, RandomSafeKesParameterSetsStayFinite) {
    Rng rng(20240605); // RandomSafeParameterSetsStayFinite's draws, with the kes law
    int tore = 0, cascades = 0;
    for (int run = 0; run < 16; ++run) {
        Settings s = randomSafeSettings(rng);
        s.material.model = MaterialModel::Kes;
        s.cloth.resolutionX = 4 + (s.cloth.resolutionX - 4) / 2; // [4, 12]
        s.cloth.resolutionY = 4 + (s.cloth.resolutionY - 4) / 2;
        ASSERT_NO_FATAL_FAILURE(runRandomSet(rng, s, run, tore, cascades, 1.5));
    }
    EXPECT_GT(tore, 0) << "some of the runs must tear, or tearing is not being tested";
    RecordProperty("cascades", std::to_string(cascades));
}

} // namespace

// Issue 12, goal 5: the guard never makes the material softer than set without saying so. Within
// its sub-step budget it keeps every spring as set; below what the material needs (here 10
// sub-steps where a 0.4 m cloth at 33 x 33 needs about 120) it caps springs and World reports how
// many and how much of the stiffness and damping the most softened one kept.
TEST(Stability, GuardReportsWhatItSoftens) {
    const std::vector<std::string> small = {"cloth.width=0.4", "cloth.height=0.4", "cloth.resolution_x=33",
                                            "cloth.resolution_y=33", "sleep.enabled=0"};
    World asSet;
    ASSERT_EQ(loadScene(asSet, "curtain", small), "");
    asSet.step();
    EXPECT_GT(asSet.frameSubsteps, 10);
    EXPECT_EQ(asSet.guardCappedSprings, 0u);
    EXPECT_EQ(asSet.guardStiffnessKept, 1.f);
    EXPECT_EQ(asSet.guardDampingKept, 1.f);

    std::vector<std::string> budget = small;
    budget.push_back("time.max_substeps=10");
    World capped;
    ASSERT_EQ(loadScene(capped, "curtain", budget), "");
    capped.step();
    EXPECT_EQ(capped.frameSubsteps, 10);
    EXPECT_GT(capped.guardCappedSprings, 0u);
    EXPECT_LE(capped.guardCappedSprings, capped.cloth.springs.size() + capped.cloth.bends.size());
    EXPECT_GT(capped.guardStiffnessKept, 0.f);
    EXPECT_LT(capped.guardStiffnessKept, 1.f);
    EXPECT_LT(capped.guardDampingKept, 1.f);
}

// The figures the guard reports, against Gershgorin's bound worked by hand. Two oscillators
// (test::buildOscillator's triangle, and the same twice as large far beside it: the same spring
// weight, area / L^2 = 1/2, and four times the mass at its free corner), no gravity or air, one
// sub-step of dt = 1 ms. A free corner's load is w dt^2 sum(k) / 2 + w dt sum(kd), with w = 3 /
// (density x area), sum(k) = S and sum(kd) = D over its two springs: at S = 8e5 N/m and D = 10 N s/m,
// 6.0 + 0.15 at the small one's and a quarter of that at the large one's. The guard scales each
// corner's two springs by budget / load (0.9 / 6.15 and 0.9 / 1.5375), the springs between the
// pinned corners not at all, and reports the most softened spring's share of its stiffness and of
// its damping (both the small oscillator's) and the four springs it scaled.
TEST(Stability, GuardReportsTheMostSoftenedSpringsShareOfTheMaterial) {
    World w;
    w.settings = test::quietSettings();
    Settings& s = w.settings;
    s.material.stretchStiffness = 8e5f;
    s.material.stretchDamping = 10.f;
    s.material.bendStiffness = 0.f;
    s.material.density = 0.2f; // kg/m^2: the small free corner's third of its unit area is 1/15 kg
    s.time.frameDt = 1e-3f;
    s.time.substeps = 1;
    s.time.maxSubsteps = 1;
    s.time.damping = DampingMode::Explicit; // taken implicitly, the damping would not count
    s.sleep.enabled = false;
    MeshData m;
    m.positions = {{-1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {8, 0, 0}, {12, 0, 0}, {10, 2, 0}};
    m.triangles = {{0, 1, 2}, {3, 4, 5}};
    m.cornerUVs = {{Vec2d(0, 0), Vec2d(1, 0), Vec2d(0.5, 1)}, {Vec2d(0, 0), Vec2d(1, 0), Vec2d(0.5, 1)}};
    ASSERT_EQ(w.rebuild(m), "");
    for (const int p : {0, 1, 3, 4}) w.cloth.setPinned(p, true);
    w.step();
    const double dt = 1e-3, wSmall = 3.0 / (0.2 * 1.0);
    const double loadSmall = wSmall * dt * dt * 8e5 / 2 + wSmall * dt * 10.0;
    ASSERT_NEAR(loadSmall, 6.15, 1e-9);
    EXPECT_NEAR(w.guardStiffnessKept, 0.9 / loadSmall, 1e-5);
    EXPECT_NEAR(w.guardDampingKept, 0.9 / loadSmall, 1e-5);
    EXPECT_EQ(w.guardCappedSprings, 4u);
    // The large oscillator alone: its own share (0.9 / 1.5375), not the small one's.
    World large;
    large.settings = s;
    MeshData one;
    one.positions = {{8, 0, 0}, {12, 0, 0}, {10, 2, 0}};
    one.triangles = {{0, 1, 2}};
    one.cornerUVs = {m.cornerUVs.front()};
    ASSERT_EQ(large.rebuild(one), "");
    large.cloth.setPinned(0, true);
    large.cloth.setPinned(1, true);
    large.step();
    EXPECT_NEAR(large.guardStiffnessKept, 0.9 / (loadSmall / 4), 1e-5);
    EXPECT_EQ(large.guardCappedSprings, 2u);
}

// ========================================================================================== [DAMPING]

namespace {

// The oscillator (test::buildOscillator) with spring damping, one sub-step of dt a frame, the guard
// off: C's displacement u = y - 1 after each step. Its springs AC and BC each have k = S / 2 and
// kd = D / 2 (weight 1/2) and lie at 45 degrees to u, so u'' + (kd / m) u' + (k / m) u = 0 with
// m = rho / 3 (C's third of the unit triangle).
std::vector<double> dampedOscillator(float stiffness, float damping, float dt, bool implicitDamping, int steps) {
    World w;
    w.settings = test::quietSettings();
    Settings& s = w.settings;
    s.material.stretchStiffness = stiffness;
    s.material.stretchDamping = damping;
    s.material.bendStiffness = 0.f;
    s.material.bendDamping = 0.f;
    s.time.frameDt = dt;
    s.time.substeps = 1;
    s.time.stabilityGuard = false;
    s.time.damping = implicitDamping ? DampingMode::Implicit : DampingMode::Explicit;
    s.sleep.enabled = false;
    EXPECT_EQ(test::buildOscillator(w), "");
    std::vector<double> u;
    for (int n = 0; n < steps; ++n) {
        w.step();
        u.push_back(double(w.cloth.x[2].y()) - 1.0);
    }
    return u;
}

// Taken implicitly, the damping of a slow mode is the material's: at omega dt = 0.02 the amplitude
// of the lightly damped oscillator (zeta = 0.1) falls per period as exp(-gamma T_d / 2), within 2 %
// of the log decrement, as the explicit damping does.
TEST(Stability, ImplicitDampingDampsASlowModeAsTheMaterialSays) {
    const double rho = 0.2, m = rho / 3.0, S = 60.0, k = S / 2.0;
    const double omega = std::sqrt(k / m), zeta = 0.1, gamma = 2.0 * zeta * omega;
    const double D = 2.0 * gamma * m; // kd = D / 2 = gamma m
    const double dt = 0.02 / omega, periodD = 2.0 * M_PI / (omega * std::sqrt(1.0 - zeta * zeta));
    const double decrement = 0.5 * gamma * periodD; // ln(amplitude ratio) per period
    for (bool implicitDamping : {false, true}) {
        const std::vector<double> u = dampedOscillator(float(S), float(D), float(dt), implicitDamping, 2000);
        std::vector<double> peaks; // the upper peaks
        for (size_t i = 1; i + 1 < u.size(); ++i)
            if (u[i] > u[i - 1] && u[i] >= u[i + 1]) peaks.push_back(u[i]);
        ASSERT_GE(peaks.size(), 5u) << "implicit " << implicitDamping;
        const double measured = std::log(peaks[0] / peaks[4]) / 4.0;
        EXPECT_NEAR(measured, decrement, 0.02 * decrement) << "implicit " << implicitDamping;
    }
}

// Damping 2,500 x stronger (gamma dt = 5): explicit damping multiplies the velocity by about
// 1 - gamma dt = -4 a step and blows up; taken implicitly the oscillator, now overdamped, creeps
// back without crossing zero, never past its start.
TEST(Stability, ImplicitDampingIsStablePastTheExplicitBound) {
    const double rho = 0.2, m = rho / 3.0, S = 60.0, k = S / 2.0, omega = std::sqrt(k / m);
    const double dt = 0.02 / omega, gamma = 5.0 / dt;
    const float D = float(2.0 * gamma * m);
    const std::vector<double> explicitRun = dampedOscillator(float(S), D, float(dt), false, 200);
    const bool blewUp = !std::isfinite(explicitRun.back()) || std::abs(explicitRun.back()) > 1.0;
    EXPECT_TRUE(blewUp) << "the explicit damping should not survive gamma dt = 5: u = " << explicitRun.back();
    const std::vector<double> u = dampedOscillator(float(S), D, float(dt), true, 2000);
    const double u0 = 1e-3;
    for (size_t i = 0; i < u.size(); ++i) {
        ASSERT_TRUE(std::isfinite(u[i])) << "step " << i;
        ASSERT_GT(u[i], 0.0) << "step " << i;
        ASSERT_LE(u[i], u0 * (1.0 + 1e-4)) << "step " << i;
    }
    EXPECT_LT(u.back(), u[0]); // it does move back
}

// The 0.4 m curtain at n x n, sleep off, with `extra` settings, after its first frame.
World smallCurtainFirstFrame(int n, const std::vector<std::string>& extra) {
    std::vector<std::string> sets = {"cloth.width=0.4", "cloth.height=0.4", "sleep.enabled=0",
                                     "cloth.resolution_x=" + std::to_string(n), "cloth.resolution_y=" + std::to_string(n)};
    sets.insert(sets.end(), extra.begin(), extra.end());
    World w;
    EXPECT_EQ(loadScene(w, "curtain", sets), "");
    w.step();
    EXPECT_TRUE(w.finite);
    return w;
}

// With the damping taken implicitly the guard's step follows the springs' stiffness alone: a 0.4 m
// curtain takes the sub-steps it takes with no damping at all, at 33 and 65 a side, fewer than with
// the damping explicit (it bounds the step by m / sum(kd), which falls as the spacing squared), and
// keeps the material as set.
TEST(Stability, ImplicitDampingLeavesTheGuardsStepToTheStiffness) {
    auto substeps = [](int n, const std::vector<std::string>& extra) {
        const World w = smallCurtainFirstFrame(n, extra);
        EXPECT_EQ(w.guardCappedSprings, 0u) << n;
        EXPECT_EQ(w.profile.dampingImplicit, !extra.empty() && extra[0] == "time.damping=implicit") << n;
        return w.frameSubsteps;
    };
    for (int n : {33, 65}) {
        const int explicitDamping = substeps(n, {"time.damping=explicit"});
        const int implicitDamping = substeps(n, {"time.damping=implicit"});
        const int undamped = substeps(n, {"time.damping=explicit", "material.stretch_damping=0", "material.bend_damping=0"});
        EXPECT_EQ(implicitDamping, undamped) << n;
        EXPECT_LT(implicitDamping * 3, explicitDamping * 2) << n; // at least a third fewer
    }
}

// time.damping = auto (the default) takes the damping implicitly where its sub-steps, each costing
// kImplicitDampingCost explicit ones, are the cheaper way to keep the material: the 0.4 m curtain at
// 65 a side (86 implicit sub-steps against 189), not at 33 (43 x 1.6 against 66) nor the 2 m curtain
// at 40 (the floor of time.substeps either way). The guard's two estimates come from one walk over
// the springs (guardStepEstimates) and equal the single ones.
TEST(Stability, AutoDampingTakesTheCheaperStep) {
    struct Case {
        double size;
        int n;
        bool implicitExpected;
    };
    for (const Case c : {Case{0.4, 33, false}, Case{0.4, 65, true}, Case{2.0, 40, false}}) {
        auto frame = [&](const std::string& damping) {
            World w;
            const std::string side = std::to_string(c.size);
            const std::vector<std::string> sets = {"cloth.width=" + side, "cloth.height=" + side, "sleep.enabled=0",
                                                   "cloth.resolution_x=" + std::to_string(c.n),
                                                   "cloth.resolution_y=" + std::to_string(c.n), "time.damping=" + damping};
            EXPECT_EQ(loadScene(w, "curtain", sets), "");
            w.step();
            EXPECT_TRUE(w.finite);
            return w;
        };
        const World explicitWorld = frame("explicit"), implicitWorld = frame("implicit"), autoWorld = frame("auto");
        const int floor = autoWorld.settings.time.substeps;
        const double explicitCost = std::max(floor, explicitWorld.frameSubsteps);
        const double implicitCost = kImplicitDampingCost * std::max(floor, implicitWorld.frameSubsteps);
        EXPECT_EQ(implicitCost < explicitCost, c.implicitExpected) << c.size << " m, " << c.n;
        EXPECT_EQ(autoWorld.profile.dampingImplicit, c.implicitExpected) << c.size << " m, " << c.n;
        EXPECT_EQ(autoWorld.frameSubsteps,
                  c.implicitExpected ? implicitWorld.frameSubsteps : explicitWorld.frameSubsteps);
        EXPECT_EQ(autoWorld.guardCappedSprings, 0u);
        EXPECT_EQ(autoWorld.profile.dampingImplicitSubsteps, c.implicitExpected ? uint64_t(autoWorld.frameSubsteps) : 0u);
        for (bool interacting : {false, true}) {
            const GuardSteps both = guardStepEstimates(autoWorld.cloth, autoWorld.settings, kGuardLightMass, interacting);
            EXPECT_EQ(both.withDamping,
                      guardStepEstimate(autoWorld.cloth, autoWorld.settings, kGuardLightMass, interacting, false));
            EXPECT_EQ(both.dampingFree,
                      guardStepEstimate(autoWorld.cloth, autoWorld.settings, kGuardLightMass, interacting, true));
            EXPECT_LE(both.withDamping, both.dampingFree); // equal where a stiffness cap decides
        }
    }
}

// time.damping = auto (the default): where the explicit damping's step would be past
// time.max_substeps, so that the guard would soften the cloth, the damping is taken implicitly and
// the material stays as set. The 0.4 m curtain at 129 a side: explicitly the guard asks 644
// sub-steps and softens every spring at 200; auto takes the stiffness's 172 and caps none. Where
// the implicit step would not fit either (max_substeps 100), auto stays explicit and softens.
TEST(Stability, AutoDampingKeepsTheMaterialWhereExplicitDampingWouldSoftenIt) {
    auto run = [](const std::vector<std::string>& extra) {
        const World w = smallCurtainFirstFrame(129, extra);
        return std::pair<int, size_t>(w.frameSubsteps, w.guardCappedSprings);
    };
    const auto [explicitSteps, explicitCapped] = run({"time.damping=explicit"});
    EXPECT_EQ(explicitSteps, 200);
    EXPECT_GT(explicitCapped, 0u);
    const auto [autoSteps, autoCapped] = run({});
    const auto [undampedSteps, undampedCapped] =
        run({"time.damping=explicit", "material.stretch_damping=0", "material.bend_damping=0"});
    EXPECT_EQ(autoSteps, undampedSteps);
    EXPECT_LT(autoSteps, 200);
    EXPECT_EQ(autoCapped, 0u);
    EXPECT_EQ(undampedCapped, 0u);
    const auto [tightSteps, tightCapped] = run({"time.max_substeps=100"});
    EXPECT_EQ(tightSteps, 100);
    EXPECT_GT(tightCapped, 0u);
}

} // namespace
