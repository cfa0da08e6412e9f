// Mode `skipping`: per-phase timings of every library scene, and what each kind of skipping saves:
// phases a scene does not need (no balls, no wind, no tearing), sleep (a cloth at rest is not
// simulated until something can touch it) and the ball broad phase (only triangles of particles
// near a ball are tested).
//
// Each saving is measured as two runs of the same world that differ only in the one thing: frames
// are timed after the world has run 2 s (settled), fastest of three copies (the machine is shared;
// other work only adds time). One OpenMP thread unless --threads says otherwise.
#include "common.h"
#include "report.h"

#include <algorithm>
#include <cstdio>

namespace clothtear::bench {
namespace {

// Milliseconds per frame over `frames` frames, fastest of three runs of copies of `w`.
double msPerFrame(const World& w, int frames) {
    double best = 1e300;
    for (int rep = 0; rep < 3; ++rep) {
        World c = w;
        const auto t0 = std::chrono::steady_clock::now();
        for (int f = 0; f < frames; ++f)
            c.step();
        best = std::min(best, 1000.0 * secondsSince(t0) / frames);
    }
    return best;
}

World settledWorld(const std::string& scene, std::vector<std::string> o, double seconds = 2.0) {
    World w = loadOrThrow(scene, o);
    for (int f = 0; f < int(seconds * 60); ++f)
        w.step();
    w.profile.reset();
    return w;
}

} // namespace

int runSkipping(const BenchOptions& opt) {
    setThreads(opt.threads);
    const int frames = opt.quick ? 20 : 60;
    std::printf("\n== per-phase timings (ms per 1/60 s frame, 2 s per scene from its start, %d thread(s))\n",
                opt.threads);
    Csv phases(opt.out + "/skipping_phases.csv",
               {"scene", "particles", "phase", "ms_per_frame", "runs_per_frame"});
    std::printf("  %-16s %9s", "scene", "particles");
    for (int p = 0; p < int(Phase::Count); ++p)
        std::printf(" %9s", phaseName(Phase(p)));
    std::printf(" %9s\n", "total");
    for (const SceneDef& sd : allScenes()) {
        World w = loadOrThrow(sd.name, {"sleep.enabled=false"});
        const int n = opt.quick ? 30 : 120;
        for (int f = 0; f < n; ++f)
            w.step();
        std::printf("  %-16s %9zu", sd.name, w.cloth.particleCount());
        double total = 0;
        for (int p = 0; p < int(Phase::Count); ++p) {
            const double ms = w.profile.ms[p] / n;
            total += ms;
            phases.row(sd.name, w.cloth.particleCount(), phaseName(Phase(p)), ms,
                       double(w.profile.runs[p]) / n);
            std::printf(" %9.3f", ms);
        }
        std::printf(" %9.3f\n", total);
    }

    std::printf("\n== what skipping saves (ms per frame, fastest of 3, after 2 s)\n");
    Csv gains(opt.out + "/skipping_gains.csv",
              {"what", "resolution", "with_ms_per_frame", "without_ms_per_frame", "saved_fraction"});
    const int res = opt.quick ? 32 : 64;
    const std::string r = std::to_string(res);
    const std::vector<std::string> curtain = {"cloth.resolution_x=" + r, "cloth.resolution_y=" + r,
                                              "sleep.enabled=false"};
    auto report = [&](const char* what, double skipped, double entered) {
        gains.row(what, res, skipped, entered, 1.0 - skipped / entered);
        std::printf("  %-58s %8.3f vs %8.3f ms  (saves %4.1f%%)\n", what, skipped, entered,
                    100.0 * (1.0 - skipped / entered));
    };
    {
        // A ball resting on the ground 10 m away: the ball phases run every sub-step but find nothing.
        World none = settledWorld("curtain", curtain);
        World far = none;
        Ball b;
        b.radius = 0.5f;
        b.x = Vec3(10.f, far.settings.collision.groundHeight + b.radius, 0.f);
        far.balls.push_back(b);
        World farAll = far;
        farAll.settings.collision.broadPhase = false;
        const double a = msPerFrame(none, frames), bb = msPerFrame(far, frames),
                     c = msPerFrame(farAll, frames);
        report("balls absent (skipped) vs a ball far away, broad phase", a, bb);
        report("balls absent (skipped) vs a ball far away, every triangle", a, c);
    }
    {
        World off = settledWorld("curtain", curtain);
        World on = off;
        on.settings.wind.enabled = true;
        on.settings.wind.speed = 1e-6f; // entered, no visible force
        report("wind off (skipped) vs wind on at 1e-6 m/s", msPerFrame(off, frames), msPerFrame(on, frames));
    }
    {
        std::vector<std::string> o = curtain;
        o.push_back("tear.enabled=false");
        World off = settledWorld("curtain", o);
        World on = off;
        on.settings.tear.enabled = true;
        report("tearing off vs on (limit on: the scan is the limit's)", msPerFrame(off, frames),
               msPerFrame(on, frames));
        World offNoLimit = off, onNoLimit = off;
        offNoLimit.settings.limit.enabled = false;
        onNoLimit.settings.limit.enabled = false;
        onNoLimit.settings.tear.enabled = true;
        report("tearing off vs on, limit off (limit phase skipped)", msPerFrame(offNoLimit, frames),
               msPerFrame(onNoLimit, frames));
    }
    {
        std::vector<std::string> o = {"cloth.resolution_x=" + r, "cloth.resolution_y=" + r};
        World sleeping = settledWorld("curtain", o, 10.0);
        World awake = sleeping;
        awake.settings.sleep.enabled = false;
        awake.wake();
        std::printf("  (curtain after 10 s: %s, fastest particle %.2e m/s)\n",
                    sleeping.asleep ? "asleep" : "AWAKE", sleeping.maxSpeed);
        report("pinned cloth at rest: asleep vs simulated", msPerFrame(sleeping, frames),
               msPerFrame(awake, frames));
    }
    // A ball in the cloth: the broad phase pays when the ball (with the margin) covers under an
    // eighth of the cloth (a 0.2 m ball on the 6 m cloth); the 1 m ball covers more: full scan.
    struct BallCase {
        const char* radius;
        int res;
    };
    const std::vector<BallCase> cases = opt.quick
                                            ? std::vector<BallCase>{{"0.2", 32}}
                                            : std::vector<BallCase>{{"0.2", 64}, {"0.2", 128}, {"1", 128}};
    for (const BallCase& bc : cases) {
        const std::string br = std::to_string(bc.res);
        World broad = loadOrThrow("ball-r1-v3-high", {"cloth.resolution_x=" + br, "cloth.resolution_y=" + br,
                                                      std::string("ball.radius=") + bc.radius});
        for (int f = 0; f < 12; ++f)
            broad.step(); // the ball is at the cloth
        World all = broad;
        all.settings.collision.broadPhase = false;
        const double a = msPerFrame(broad, frames / 2), b = msPerFrame(all, frames / 2);
        const std::string what = std::string("ball broad phase, r = ") + bc.radius + " m ball in the " + br +
                                 "x" + br + " cloth (ball-r1-v3-high)";
        gains.row(what, bc.res, a, b, 1.0 - a / b);
        std::printf("  %-58s %8.3f vs %8.3f ms  (saves %4.1f%%)\n", what.c_str(), a, b,
                    100.0 * (1.0 - a / b));
    }
    return 0;
}

} // namespace clothtear::bench
