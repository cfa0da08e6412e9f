// Mode `stability`: for each integrator, the largest stable sub-step against stiffness and against
// density, found by bisection, with the stability guard's estimate (stableStepEstimate) beside it.
//
// The test: the `swing` scene at 16 x 16 (a large motion that excites every mode) plus a seeded
// random velocity of 1 cm/s on every particle, guard and length limit off, tearing off, run for
// 1 simulated second at sub-step dt (one sub-step per frame). Unstable: any NaN/Inf, the energy
// (kinetic + springs) above 10x (its start + what gravity can give: total mass x |g| x cloth size),
// or a structural strain above 10. Bisection on log(dt) in [1e-5, 0.05] s, 12 halvings (0.2% of
// a decade); "stable at 0.05 s" is reported as 0.05 (the references are stable at any step).
#include "clothtear/random.h"
#include "common.h"
#include "report.h"

#include <cmath>
#include <cstdio>

namespace clothtear::bench {
namespace {

constexpr double kLo = 1e-5, kHi = 0.05;

double springEnergy(const World& w) {
    double e = 0;
    auto add = [&](const std::vector<Spring>& springs, double k) {
        for (const Spring& s : springs) {
            const double ext = double((w.cloth.x[s.b] - w.cloth.x[s.a]).norm()) - s.rest;
            e += 0.5 * k * s.weight * ext * ext;
        }
    };
    add(w.cloth.springs, w.settings.material.stretchStiffness);
    add(w.cloth.bends, w.settings.material.bendStiffness);
    return e;
}

World testWorld(const char* integrator, double dt, double stiffness, double density) {
    World w = loadOrThrow("swing", {"cloth.resolution_x=16", "cloth.resolution_y=16", "limit.enabled=false",
                                    "time.stability_guard=false", "sleep.enabled=false", "time.substeps=1",
                                    "time.frame_dt=" + num(dt), std::string("time.integrator=") + integrator,
                                    "material.stretch_stiffness=" + num(stiffness),
                                    "material.density=" + num(density)});
    Rng rng(7);
    for (Index p = 0; p < w.cloth.particleCount(); ++p)
        if (!w.cloth.pinned(p))
            w.cloth.v[p] =
                0.01f * Vec3(float(rng.uniform(-1, 1)), float(rng.uniform(-1, 1)), float(rng.uniform(-1, 1)));
    return w;
}

bool stable(const char* integrator, double dt, double stiffness, double density) {
    World w = testWorld(integrator, dt, stiffness, density);
    const double scale = w.kineticEnergy() + springEnergy(w) + w.cloth.totalMass() * 9.81 * 2.0;
    const int frames = int(std::ceil(1.0 / dt));
    for (int f = 0; f < frames; ++f) {
        w.step();
        if (!w.finite || w.maxStrain > 10.f)
            return false;
        if (f % 16 == 0 || f == frames - 1)
            if (!(w.kineticEnergy() + springEnergy(w) <= 10 * scale))
                return false;
    }
    return true;
}

double largestStable(const char* integrator, double stiffness, double density) {
    if (stable(integrator, kHi, stiffness, density))
        return kHi;
    double lo = kLo, hi = kHi;
    if (!stable(integrator, lo, stiffness, density))
        return 0;
    for (int i = 0; i < 12; ++i) {
        const double mid = std::sqrt(lo * hi);
        (stable(integrator, mid, stiffness, density) ? lo : hi) = mid;
    }
    return lo;
}

} // namespace

int runStability(const BenchOptions& opt) {
    setThreads(opt.threads);
    const std::vector<double> stiffnesses =
        opt.quick ? std::vector<double>{10, 1000} : std::vector<double>{1, 10, 100, 1000, 1e4, 1e5};
    const std::vector<double> densities =
        opt.quick ? std::vector<double>{0.2} : std::vector<double>{0.01, 0.1, 1, 10};
    const char* integrators[] = {"semi-implicit-euler", "forward-euler", "verlet", "implicit-euler", "xpbd"};
    Csv csv(opt.out + "/stability.csv",
            {"sweep", "integrator", "stiffness_N_per_m", "density_kg_per_m2", "largest_stable_dt_s",
             "guard_estimate_s", "measured_over_estimate"});
    std::printf("\n== stability (largest stable sub-step, 16x16 swing, guard and limit off; 0.05 = stable at "
                "the bound)\n");
    for (int sweep = 0; sweep < 2; ++sweep) {
        const std::vector<double>& values = sweep == 0 ? stiffnesses : densities;
        Plot plot{sweep == 0 ? "largest stable sub-step against stiffness (density 0.2 kg/m^2)"
                             : "largest stable sub-step against density (stiffness 60 N/m)",
                  sweep == 0 ? "material.stretch_stiffness (N/m)" : "material.density (kg/m^2)",
                  "largest stable dt (s)",
                  true,
                  true,
                  {},
                  {}};
        Series estimate{"guard estimate", {}, true, false};
        for (const char* integ : integrators) {
            Series s{integ, {}, false, false};
            std::printf("  %-20s", integ);
            for (double v : values) {
                const double S = sweep == 0 ? v : 60.0, rho = sweep == 0 ? 0.2 : v;
                const double dt = largestStable(integ, S, rho);
                const World w = testWorld("semi-implicit-euler", 1e-3, S, rho);
                const double est = stableStepEstimate(w.cloth, w.settings);
                csv.row(sweep == 0 ? "stiffness" : "density", integ, S, rho, dt, est, dt / est);
                std::printf(" %g:%.3g", v, dt);
                std::fflush(stdout);
                if (dt > 0)
                    s.points.emplace_back(v, dt);
                if (integ == integrators[0])
                    estimate.points.emplace_back(v, est);
            }
            std::printf("\n");
            plot.series.push_back(s);
        }
        plot.series.push_back(estimate);
        plot.notes = {opt.commandLine, machineDescription() + "; 0.05 s = stable at the largest step tried"};
        writeSvg(plot, opt.out + (sweep == 0 ? "/stability_stiffness.svg" : "/stability_density.svg"));
    }
    return 0;
}

} // namespace clothtear::bench
