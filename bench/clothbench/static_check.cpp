// Mode `static`: static accuracy. The direct static solve (Newton on the spring energy,
// static_solve.h) at 32, 64 and 128 particles per side (mesh refinement of the model), against the
// settled dynamics of the same curtain: the spring model (limit and guard off, as many sub-steps as
// the stable-step estimate needs, so no spring is capped) and the app's defaults (limit on, guard at
// 10 sub-steps: springs capped at fine meshes). Settled: 5 s with air drag 2 kg/(m^2 s), which
// changes the motion, not the equilibrium. Sag = drop of the bottom-centre particle(s).
#include "clothtear/static_solve.h"
#include "common.h"
#include "report.h"

#include <cmath>
#include <cstdio>

namespace clothtear::bench {
namespace {


} // namespace

int runStatic(const BenchOptions& opt) {
    setThreads(opt.threads);
    Csv csv(opt.out + "/static.csv", {"resolution", "model", "sag_m", "static_sag_m", "sag_vs_static",
                                      "rms_vs_static_m", "newton_iterations", "newton_residual",
                                      "static_solve_s", "settle_s", "substeps_per_frame", "max_strain"});
    std::printf(
        "\n== static accuracy (curtain 2 m, bottom-centre sag; static = Newton on the spring energy)\n");
    std::vector<int> resolutions = opt.quick ? std::vector<int>{16, 32} : std::vector<int>{32, 64, 128};
    double firstStatic = 0;
    for (int res : resolutions) {
        const std::string r = std::to_string(res);
        const std::vector<std::string> base = {"cloth.resolution_x=" + r,
                                               "cloth.resolution_y=" + r,
                                               "tear.enabled=false",
                                               "collision.ground=false",
                                               "air.drag=2",
                                               "sleep.enabled=false"};
        World w0 = loadOrThrow("curtain", base);
        auto t0 = std::chrono::steady_clock::now();
        const StaticSolveResult st = solveStatic(w0.cloth, w0.settings, w0.cloth.x);
        const double solveSeconds = secondsSince(t0);
        const double staticSag = bottomCentreSag(w0.cloth, w0.settings.cloth, st.x);
        if (firstStatic == 0)
            firstStatic = staticSag;
        std::printf("  %3dx%-3d static sag %.6f m (%d Newton iterations, residual %.1e, %.2f s)%s\n", res,
                    res, staticSag, st.iterations, st.residual, solveSeconds,
                    st.converged ? "" : " NOT CONVERGED");
        csv.row(res, "static", staticSag, staticSag, 1.0, 0.0, st.iterations, st.residual, solveSeconds, 0.0,
                0, 0.0);
        struct Model {
            const char* name;
            std::vector<std::string> extra;
        };
        // The spring model with the guard off and as many sub-steps as the stable-step estimate
        // needs (with the guard on, its per-spring cap would still soften springs: the "app" row).
        const int need =
            int(std::ceil(double(w0.settings.time.frameDt) / stableStepEstimate(w0.cloth, w0.settings)));
        const Model models[] = {
            {"springs",
             {"limit.enabled=false", "time.stability_guard=false",
              "time.substeps=" + std::to_string(std::max(need, w0.settings.time.substeps))}},
            {"app", {}}};
        for (const Model& m : models) {
            std::vector<std::string> o = base;
            o.insert(o.end(), m.extra.begin(), m.extra.end());
            World w = loadOrThrow("curtain", o);
            t0 = std::chrono::steady_clock::now();
            for (int f = 0; f < 5 * 60; ++f)
                w.step();
            const double settle = secondsSince(t0);
            const double sag = bottomCentreSag(w.cloth, w.settings.cloth, w.cloth.x);
            double sum = 0;
            for (Index p = 0; p < w.cloth.particleCount(); ++p)
                sum += (w.cloth.x[p].cast<double>() - st.x[p]).squaredNorm();
            const double rms = std::sqrt(sum / double(w.cloth.particleCount()));
            csv.row(res, m.name, sag, staticSag, sag / staticSag, rms, 0, 0.0, 0.0, settle, w.frameSubsteps,
                    w.maxStrain);
            std::printf("           %-8s settled sag %.6f m (%.4fx static, RMS from static %.2e m, %d "
                        "sub-steps/frame, "
                        "max strain %.3f, %.1f s)%s\n",
                        m.name, sag, sag / staticSag, rms, w.frameSubsteps, w.maxStrain, settle,
                        w.finite ? "" : " NON-FINITE");
        }
        std::printf("           static sag vs %dx%d: %+.3f%%\n", resolutions[0], resolutions[0],
                    100.0 * (staticSag / firstStatic - 1.0));
    }
    return 0;
}

} // namespace clothtear::bench
