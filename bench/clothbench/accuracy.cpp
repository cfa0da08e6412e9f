// Mode `accuracy`: run time against error for every integrator on the same scenes.
//
// Error: RMS distance of the particles from a reference run of the same scene and model with a
// much smaller sub-step, at fixed times (0.5, 1 and 2 s), divided by the cloth size (its larger
// side). Only particles that exist from the start are compared (tearing appends particles). The
// reference's own error is estimated by running it again at half its sub-step: the change must be
// far below the errors reported (accuracy_reference.csv).
//
// The reference's sub-step is not as small as it could be: the state is float, and round-off
// (about 1e-7 of the position per step, amplified where the cloth folds) grows with the number of
// steps. Verlet's halving change on the swing at 0.5 s was 2e-6 at 64 -> 128 sub-steps per frame
// and 9e-5 at 2048 -> 4096 (measured): below 1/3840 s more steps only add noise. So the springs
// model uses Verlet (second order) at 128 sub-steps per frame, 16x finer than the finest explicit
// point worth having; the app model (whose limit and contacts Verlet treats differently) uses
// semi-implicit Euler at 1024.
//
// Models: "springs" is the scene as a smooth ODE (no length limit, no stability guard, no Verlet
// friction): every integrator converges to the same solution and the measured order is the
// integrator's. "app" is the scene as the app runs it (limit, guard, and for `ball-r1-v3-high`
// tearing): contacts, the limit's projection and tears are not smooth, so the order there is what
// a user gets, not a property of the integrator.
//
// Each point is (wall time per simulated second, error at 1 s); the fastest of up to three runs
// (the machine is shared, other work only adds time). Convergence order: least-squares slope of
// log(error at 0.5 s) against log(dt) over the points between 20x the reference's own change and 5%.
// Why 0.5 s for the order: the swing is chaotic once it folds (after about 0.75 s at 32 x 32), and
// float round-off (about 1e-7 per step) grows to 1e-4..1e-3 of the cloth size by 1 s whatever the
// step: Verlet at 32 and at 64 sub-steps per frame differ by 2e-6 at 0.5 s and 2e-4 at 1 s
// (measured). Errors at 1 s below that floor do not measure the integrator.
#include "common.h"
#include "report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>

namespace clothtear::bench {
namespace {

struct AccuracyScene {
    const char* scene;
    const char* model;
    std::vector<std::string> overrides;
    const char* referenceIntegrator; // the most accurate integrator valid for the model
    int referenceSubsteps;           // per 1/60 s frame
};

const double kTimes[] = {0.5, 1.0, 2.0};
constexpr int kPlotTime = 1; // index into kTimes: the run-time plot and the pick use the error at 1 s
constexpr int kFitTime = 0;  // the orders and the error-against-dt plot use the error at 0.5 s

const std::vector<std::string> kSmooth = {"limit.enabled=false", "time.stability_guard=false",
                                          "time.verlet_friction=0"};

std::vector<AccuracyScene> scenes(bool quick) {
    auto with = [](std::vector<std::string> a, const std::vector<std::string>& b) {
        a.insert(a.end(), b.begin(), b.end());
        return a;
    };
    const std::vector<std::string> res32 = {"cloth.resolution_x=32", "cloth.resolution_y=32"};
    std::vector<AccuracyScene> s = {
        {"swing", "springs", with(res32, kSmooth), "verlet", 128},
        {"swing", "app", res32, "semi-implicit-euler", 1024},
    };
    if (quick)
        return s;
    s.push_back({"curtain", "springs", with(with(res32, kSmooth), {"tear.enabled=false"}), "verlet", 128});
    s.push_back({"drop", "app", res32, "semi-implicit-euler", 1024});
    s.push_back({"ball-r1-v3-high", "app", {}, "semi-implicit-euler", 1024});
    return s;
}

struct Integ {
    const char* name;
    std::vector<int> substeps;
};

std::vector<Integ> integrators(bool quick) {
    if (quick)
        return {{"semi-implicit-euler", {4, 8, 16, 32, 64}},
                {"forward-euler", {8, 16, 32, 64}},
                {"verlet", {4, 8, 16, 32, 64}},
                {"implicit-euler", {1, 2, 4, 8}},
                {"xpbd", {4, 8, 16, 32, 64}}};
    // Semi-implicit Euler also at the app's default (10) and between 16 and 32, where the app
    // model crosses 1%: the default's own error is then measured, not interpolated.
    return {{"semi-implicit-euler", {1, 2, 4, 8, 10, 16, 20, 24, 32, 64, 128, 256}},
            {"forward-euler", {1, 2, 4, 8, 16, 32, 64, 128, 256}},
            {"verlet", {1, 2, 4, 8, 16, 32, 64, 128, 256}},
            {"implicit-euler", {1, 2, 4, 8, 16, 32, 64}},
            {"xpbd", {1, 2, 4, 8, 16, 32, 64, 128, 256}}};
}

struct Run {
    std::vector<std::vector<Vec3>> snapshots; // positions of the original particles at kTimes
    double wallSeconds = 0;
    bool finite = true;
    double seconds = 0; // simulated
    uint64_t cgIterations = 0;
};

Run simulate(const AccuracyScene& sc, const char* integrator, int substeps) {
    std::vector<std::string> o = sc.overrides;
    o.push_back("sleep.enabled=false"); // the integrator is measured, not what sleep skips
    o.push_back(std::string("time.integrator=") + integrator);
    // Past the parameter's range (2000 sub-steps) the frame is shortened instead; the snapshot
    // times stay the same.
    int frameDiv = 1;
    while (substeps / frameDiv > 1000)
        frameDiv *= 2;
    if (frameDiv > 1)
        o.push_back("time.frame_dt=" + num(1.0 / 60.0 / frameDiv));
    o.push_back("time.substeps=" + std::to_string(substeps / frameDiv));
    World w = loadOrThrow(sc.scene, o);
    const size_t n0 = w.cloth.particleCount();
    Run r;
    const auto t0 = std::chrono::steady_clock::now();
    int frame = 0;
    for (double t : kTimes) {
        const int until = int(std::lround(t / double(w.settings.time.frameDt)));
        for (; frame < until && w.finite; ++frame)
            w.step();
        r.snapshots.emplace_back(w.cloth.x.begin(), w.cloth.x.begin() + long(n0));
    }
    r.wallSeconds = secondsSince(t0);
    r.finite = w.finite;
    r.seconds = w.time;
    r.cgIterations = w.profile.solverIterations;
    return r;
}

double size(const AccuracyScene& sc) {
    const World w = loadOrThrow(sc.scene, sc.overrides);
    return std::max(w.settings.cloth.width, w.settings.cloth.height);
}

double rmsError(const std::vector<Vec3>& a, const std::vector<Vec3>& b, double size) {
    double sum = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        const double d2 = (a[i] - b[i]).cast<double>().squaredNorm();
        sum += std::isfinite(d2) ? d2 : 1e30;
    }
    return std::sqrt(sum / double(a.size())) / size;
}

} // namespace

int runAccuracy(const BenchOptions& opt) {
    setThreads(opt.threads);
    Csv points(opt.out + "/accuracy.csv",
               {"scene", "model", "integrator", "substeps", "dt_s", "wall_s_per_sim_s", "finite", "err_t0.5",
                "err_t1", "err_t2", "cg_iterations_per_substep"});
    Csv orders(opt.out + "/accuracy_orders.csv",
               {"scene", "model", "integrator", "order_at_0.5s", "points_fitted"});
    Csv refs(opt.out + "/accuracy_reference.csv",
             {"scene", "model", "reference_integrator", "reference_substeps", "t", "change_when_halving_dt"});
    Csv picks(opt.out + "/accuracy_pick.csv",
              {"scene", "model", "target_err_t1", "integrator", "substeps", "wall_s_per_sim_s", "err_t1"});
    const std::string machine = machineDescription();
    std::printf("\n== accuracy (RMS position error / cloth size vs a small-dt reference)\n");
    bool anyScene = false;
    for (const AccuracyScene& sc : scenes(opt.quick)) {
        if (!opt.accuracyScene.empty() && opt.accuracyScene != sc.scene)
            continue;
        anyScene = true;
        const double L = size(sc);
        std::printf("\n%s / %s: reference %s at %d sub-steps per frame\n", sc.scene, sc.model,
                    sc.referenceIntegrator, sc.referenceSubsteps);
        const Run ref = simulate(sc, sc.referenceIntegrator, sc.referenceSubsteps);
        const Run ref2 = simulate(sc, sc.referenceIntegrator, 2 * sc.referenceSubsteps);
        std::vector<double> refChange;
        for (size_t k = 0; k < std::size(kTimes); ++k) {
            refChange.push_back(rmsError(ref.snapshots[k], ref2.snapshots[k], L));
            refs.row(sc.scene, sc.model, sc.referenceIntegrator, sc.referenceSubsteps, kTimes[k],
                     refChange[k]);
        }
        std::printf("  reference change when halving its dt: %.2e / %.2e / %.2e at 0.5 / 1 / 2 s%s\n",
                    refChange[0], refChange[1], refChange[2],
                    ref.finite && ref2.finite ? "" : " (NON-FINITE)");
        Plot pt{std::string("error at 1 s against run time: ") + sc.scene + " (" + sc.model + ")",
                "wall seconds per simulated second",
                "RMS error / cloth size at t = 1 s",
                true,
                true,
                {},
                {}};
        Plot pd{std::string("error at 0.5 s against sub-step: ") + sc.scene + " (" + sc.model + ")",
                "sub-step dt (s)",
                "RMS error / cloth size at t = 0.5 s",
                true,
                true,
                {},
                {}};
        struct Best {
            std::string integrator;
            int substeps = 0;
            double wall = 1e300, err = 0;
        };
        std::map<double, Best> best; // target -> cheapest point meeting it
        for (const Integ& in : integrators(opt.quick)) {
            Series st{in.name, {}, false, false}, sd{in.name, {}, false, false};
            std::vector<std::pair<double, double>> fit;
            std::printf("  %-20s", in.name);
            for (int sub : in.substeps) {
                Run r = simulate(sc, in.name, sub);
                // Fastest of three for short runs (timing noise on a shared machine).
                for (int rep = 1; rep < 3 && r.wallSeconds < 0.5; ++rep) {
                    const Run again = simulate(sc, in.name, sub);
                    r.wallSeconds = std::min(r.wallSeconds, again.wallSeconds);
                }
                const double dt = 1.0 / 60.0 / sub;
                double err[3];
                for (size_t k = 0; k < 3; ++k)
                    err[k] = r.finite ? rmsError(r.snapshots[k], ref.snapshots[k], L) : NAN;
                const double perSim = r.wallSeconds / std::max(r.seconds, 1e-9);
                const bool usable = r.finite && err[kPlotTime] < 1.0;
                points.row(sc.scene, sc.model, in.name, sub, dt, perSim, int(r.finite), err[0], err[1],
                           err[2], r.cgIterations / std::max(1.0, r.seconds * 60.0 * sub));
                std::printf(" %d:%s", sub, usable ? "" : "x");
                if (usable)
                    std::printf("%.1e", err[kPlotTime]);
                std::fflush(stdout);
                if (!usable)
                    continue;
                st.points.emplace_back(perSim, err[kPlotTime]);
                sd.points.emplace_back(dt, err[kFitTime]);
                if (err[kFitTime] > 20 * refChange[kFitTime] && err[kFitTime] < 0.05)
                    fit.emplace_back(dt, err[kFitTime]);
                for (double target : {0.01, 0.001})
                    if (err[kPlotTime] <= target && perSim < best[target].wall)
                        best[target] = Best{in.name, sub, perSim, err[kPlotTime]};
            }
            const double order = logLogSlope(fit);
            orders.row(sc.scene, sc.model, in.name, order, fit.size());
            std::printf("\n  %-20s order %.2f (%zu points)\n", "", order, fit.size());
            pt.series.push_back(st);
            pd.series.push_back(sd);
        }
        for (const auto& [target, b] : best) {
            picks.row(sc.scene, sc.model, target, b.integrator, b.substeps, b.wall, b.err);
            std::printf(
                "  cheapest with error <= %g at 1 s: %s, %d sub-steps (%.3g s per simulated s, error %.2e)\n",
                target, b.integrator.c_str(), b.substeps, b.wall, b.err);
        }
        for (Plot* p : {&pt, &pd}) {
            p->notes = {opt.commandLine,
                        machine + "; reference change at 1 s: " + std::to_string(refChange[1])};
        }
        const std::string stem = opt.out + "/accuracy_" + sc.scene + "_" + sc.model;
        writeSvg(pt, stem + ".svg");
        writeSvg(pd, stem + "_dt.svg");
    }
    if (!anyScene) {
        std::fprintf(stderr, "clothbench: --accuracy-scene '%s' is not one of the accuracy scenes\n",
                     opt.accuracyScene.c_str());
        return 2;
    }
    return 0;
}

} // namespace clothtear::bench
