// Google Benchmark cases for the step. Every case runs the `curtain` scene hanging at rest (settled
// for 1.5 simulated seconds first), with a material capped to be stable at its resolution (see
// bench_scene.h). Timings are wall clock (UseRealTime): the step uses OpenMP threads.
//
//   BM_Substep/RES/TEAR/THREADS   one sub-step; springs/s counts structural + bend-shear springs
//   BM_StrainScan/RES/TEAR/THREADS  one sub-step with Provot limiting off: what the strain scan alone
//                                 costs (tear=1 enters the limit phase only for the scan)
//   BM_SubstepOnLimit/RES/THREADS one sub-step at 1/600 s (10 a frame: the guard softens the springs
//                                 of a cloth this fine and it hangs on its tethers and the length
//                                 limit, as the 6 m scenes and a hand's pull do at their steps)
//   BM_Phases/RES/THREADS         per-phase ms of one sub-step, from World::profile
//   BM_Frame/RES/THREADS          one 1/60 s frame (the guard's sub-steps + bookkeeping); sim_s/s > 1 is
//                                 faster than real time
//   BM_DragFrames/RES/THREADS     30 frames of a hand pulling the curtain until it tears (from the
//                                 same start each iteration); ms/frame, tears, substeps/frame
//   BM_ThrowFrames/RES/THREADS    30 frames of the ball tool's default throw through the curtain
//   BM_SubstepAfterCut/RES/THREADS  the sub-step after a topology change: a 3 cm knife stroke (untimed)
//                                 before each, at a new place of a 16 x 16 lattice over the curtain;
//                                 against BM_Substep, what the caches' rebuilds after a tear cost
//
// Recommended: clothtear_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include "bench_scene.h"

#include "clothtear/knife.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>
#if CLOTHTEAR_HAVE_OPENMP
#include <omp.h>
#endif

namespace clothtear::bench {
namespace {

// Sets the OpenMP thread count for one benchmark case and restores it afterwards.
class ThreadScope {
public:
    explicit ThreadScope(int threads) {
#if CLOTHTEAR_HAVE_OPENMP
        previous_ = omp_get_max_threads();
        omp_set_num_threads(threads);
#else
        (void)threads;
#endif
    }
    ~ThreadScope() {
#if CLOTHTEAR_HAVE_OPENMP
        omp_set_num_threads(previous_);
#endif
    }
    ThreadScope(const ThreadScope&) = delete;
    ThreadScope& operator=(const ThreadScope&) = delete;

private:
    int previous_ = 1;
};

void commonCounters(benchmark::State& state, const World& w) {
    state.counters["particles"] = double(w.cloth.particleCount());
    state.counters["max_strain"] = maxStructuralStrain(w);
    state.counters["finite"] = w.finite && std::isfinite(maxStructuralStrain(w)) ? 1 : 0;
}

void BM_Substep(benchmark::State& state) {
    const int res = int(state.range(0));
    const bool tearing = state.range(1) != 0;
    ThreadScope threads(int(state.range(2)));
    World w = settledCurtain({res, tearing});
    state.SetLabel(describeMaterial(w));
    for (auto _ : state) {
        w.substep();
        benchmark::ClobberMemory();
    }
    const double springs = double(w.cloth.springs.size() + w.cloth.bends.size());
    state.counters["springs/s"] = benchmark::Counter(springs, benchmark::Counter::kIsIterationInvariantRate);
    commonCounters(state, w);
}

// The strain scan on its own: Provot limiting off, so the limit phase is entered only for the scan
// (tear=1) or not at all (tear=0); the difference is what the scan costs. Without the limit the
// soft cloth starts to fall, so every 50 sub-steps (untimed) it is put back at rest.
void BM_StrainScan(benchmark::State& state) {
    const int res = int(state.range(0));
    const bool tearing = state.range(1) != 0;
    ThreadScope threads(int(state.range(2)));
    World w = settledCurtain({res, tearing});
    w.settings.limit.enabled = false;
    const std::vector<Vec3> x0 = w.cloth.x, v0 = w.cloth.v;
    int sinceReset = 0;
    for (auto _ : state) {
        if (++sinceReset == 50) {
            state.PauseTiming();
            w.cloth.x = x0;
            w.cloth.v = v0;
            sinceReset = 0;
            state.ResumeTiming();
        }
        w.substep();
        benchmark::ClobberMemory();
    }
    state.counters["limit_runs"] = double(w.profile.runs[int(Phase::Limit)]);
    state.counters["tears"] = double(w.tearLog.events.size());
    commonCounters(state, w);
}

void BM_SubstepOnLimit(benchmark::State& state) {
    const int res = int(state.range(0));
    ThreadScope threads(int(state.range(1)));
    World w = settledCurtain({res, true});
    w.settings.time.substeps = 10; // World::substep()'s dt: 1/600 s
    for (int i = 0; i < 300; ++i) w.substep(); // half a second to settle onto the limit (untimed)
    w.profile.reset();
    for (auto _ : state) {
        w.substep();
        benchmark::ClobberMemory();
    }
    const StepProfile& p = w.profile;
    const double n = double(std::max<uint64_t>(p.substeps, 1));
    state.counters["limit_ms"] = p.ms[int(Phase::Limit)] / n;
    state.counters["tethers_skipped"] = double(p.limitTethersSkipped) / n; // share of sub-steps
    state.counters["expand_skipped"] = double(p.limitExpandSkipped) / n;
    commonCounters(state, w);
}

void BM_Phases(benchmark::State& state) {
    const int res = int(state.range(0));
    ThreadScope threads(int(state.range(1)));
    World w = settledCurtain({res, true});
    for (auto _ : state) {
        w.substep();
        benchmark::ClobberMemory();
    }
    const StepProfile& p = w.profile;
    for (int i = 0; i < int(Phase::Count); ++i) {
        if (p.runs[i] == 0) continue;
        state.counters[std::string(phaseName(Phase(i))) + "_ms"] = p.ms[i] / double(p.substeps);
    }
    commonCounters(state, w);
}

void BM_Frame(benchmark::State& state) {
    const int res = int(state.range(0));
    ThreadScope threads(int(state.range(1)));
    World w = settledCurtain({res, true});
    for (auto _ : state) {
        w.step();
        benchmark::ClobberMemory();
    }
    state.counters["sim_s/s"] =
        benchmark::Counter(w.settings.time.frameDt, benchmark::Counter::kIsIterationInvariantRate);
    commonCounters(state, w);
}

// The two ways a user tears the curtain, from the same start every iteration (the copy untimed),
// `kTearFrames` frames of World::step() timed: issue 15 goal 5's "30 FPS while tearing" is about
// these frames. Their outcome is chaotic in the bits, so compare builds with the same results (the
// counter `tears`) or over repetitions.
constexpr int kTearFrames = 30;

// kTearFrames frames from `start`, each iteration from a fresh copy; ms per frame and the tears.
void tearFrames(benchmark::State& state, const World& start) {
    uint64_t tears = 0, substeps = 0;
    double fastest = 1e300;
    std::array<double, int(Phase::Count)> phaseMs{}; // of the last iteration
    for (auto _ : state) {
        state.PauseTiming();
        World w = start;
        state.ResumeTiming();
        const auto t0 = std::chrono::steady_clock::now();
        for (int f = 0; f < kTearFrames; ++f) w.step();
        benchmark::ClobberMemory();
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        state.PauseTiming();
        fastest = std::min(fastest, ms / kTearFrames);
        tears = w.tearLog.total();
        substeps = w.profile.substeps;
        phaseMs = w.profile.ms;
        state.ResumeTiming();
    }
    // Where a frame goes (the last iteration's phase timers): under a moving hand the limit's
    // passes take most of it, and on two threads they split by region (limit.cpp, regionPasses).
    for (Phase ph : {Phase::Springs, Phase::Integrate, Phase::Limit, Phase::Tear})
        state.counters[std::string(phaseName(ph)) + "_ms"] = phaseMs[int(ph)] / kTearFrames;
    state.counters["fastest_ms_per_frame"] = fastest;
    state.counters["tears"] = double(tears);
    state.counters["substeps_per_frame"] = double(substeps) / kTearFrames;
}

void BM_SubstepAfterCut(benchmark::State& state) {
    const int res = int(state.range(0));
    ThreadScope threads(int(state.range(1)));
    World w = settledCurtain({res, true});
    w.substep(); // every cache built once
    w.profile.reset();
    int at = 0;
    size_t springsCut = 0;
    for (auto _ : state) {
        state.PauseTiming();
        const double u = -0.8 + 1.6 * double(at % 16) / 15.0, v = -0.8 + 1.6 * double(at / 16 % 16) / 15.0;
        springsCut += w.cut({Vec2d(u, v - 0.015), Vec2d(u, v + 0.015)}).springsCut;
        ++at;
        state.ResumeTiming();
        w.substep();
        benchmark::ClobberMemory();
    }
    const StepProfile& p = w.profile;
    const double n = double(std::max<uint64_t>(p.substeps, 1));
    state.counters["springs_ms"] = p.ms[int(Phase::Springs)] / n;
    state.counters["limit_ms"] = p.ms[int(Phase::Limit)] / n;
    state.counters["springs_cut"] = double(springsCut) / double(std::max(at, 1));
    commonCounters(state, w);
}

// A hand grabs the settled curtain below its middle (every particle within scene.grab_radius, in
// rest space, of the particle nearest (0.15, -0.4) m, as the drag tool holds a patch) and pulls it
// at (2.4, -1.3, -0.6) m/s: the README's drag (`assets/screenshots/tear.txt` at 128 a side), whose
// held patch moved so between its frames 5 and 6 (the drag plane faces the camera, so the hand
// also pulls the curtain out of its plane).
void BM_DragFrames(benchmark::State& state) {
    const int res = int(state.range(0));
    ThreadScope threads(int(state.range(1)));
    World start = settledCurtain({res, true});
    Index grab = 0;
    for (Index p = 0; p < start.cloth.particleCount(); ++p)
        if ((start.cloth.rest[p] - Vec3d(0.15, -0.4, 0.0)).squaredNorm() <
            (start.cloth.rest[grab] - Vec3d(0.15, -0.4, 0.0)).squaredNorm())
            grab = p;
    Driver hand{{}, Vec3(2.4f, -1.3f, -0.6f)};
    for (Index p = 0; p < start.cloth.particleCount(); ++p)
        if ((start.cloth.rest[p] - start.cloth.rest[grab]).norm() <= start.settings.scene.grabRadius) {
            start.cloth.setPinned(p, true);
            hand.particles.push_back(p);
        }
    start.drivers.push_back(hand);
    tearFrames(state, start);
}

// The ball tool's default throw (2 kg, 0.5 m, 8 m/s) from 2.5 m in front of the settled curtain at
// its middle, a little upwards as the start camera throws (`assets/screenshots/ball.txt`).
void BM_ThrowFrames(benchmark::State& state) {
    const int res = int(state.range(0));
    ThreadScope threads(int(state.range(1)));
    World start = settledCurtain({res, true});
    Ball ball;
    ball.radius = 0.5f;
    ball.mass = 2.f;
    ball.x = Vec3(0.f, 0.f, 2.5f);
    ball.v = Vec3(0.f, 1.f, -8.f);
    start.balls.push_back(ball);
    tearFrames(state, start);
}

// With repetitions, the fastest repetition is reported too: on a shared 2-core machine other work
// only ever adds time, so the minimum is the least disturbed measurement.
double fastest(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end()); }

BENCHMARK(BM_Substep)
    ->ArgNames({"res", "tear", "threads"})
    ->ArgsProduct({{64, 128, 256}, {0, 1}, {1, 2}})
    ->UseRealTime()
    ->ComputeStatistics("min", fastest)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_StrainScan)
    ->ArgNames({"res", "tear", "threads"})
    ->ArgsProduct({{128}, {0, 1}, {1, 2}})
    ->UseRealTime()
    ->ComputeStatistics("min", fastest)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SubstepOnLimit)
    ->ArgNames({"res", "threads"})
    ->ArgsProduct({{64, 128}, {1, 2}})
    ->UseRealTime()
    ->ComputeStatistics("min", fastest)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Phases)
    ->ArgNames({"res", "threads"})
    ->ArgsProduct({{64, 128, 256}, {1, 2}})
    ->UseRealTime()
    ->ComputeStatistics("min", fastest)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SubstepAfterCut)
    ->ArgNames({"res", "threads"})
    ->ArgsProduct({{64, 128}, {1, 2}})
    ->Iterations(256) // one stroke each, on a lattice of 256 places
    ->UseRealTime()
    ->ComputeStatistics("min", fastest)
    ->Unit(benchmark::kMicrosecond);
// The tearing frames: 64 and 128 a side, one and two threads, 3 iterations of 30 frames each.
void tearingFramesCase(benchmark::internal::Benchmark* b) {
    b->ArgNames({"res", "threads"})
        ->ArgsProduct({{64, 128}, {1, 2}})
        ->Iterations(3)
        ->UseRealTime()
        ->ComputeStatistics("min", fastest)
        ->Unit(benchmark::kMillisecond);
}
BENCHMARK(BM_DragFrames)->Apply(tearingFramesCase);
BENCHMARK(BM_ThrowFrames)->Apply(tearingFramesCase);
BENCHMARK(BM_Frame)
    ->ArgNames({"res", "threads"})
    ->ArgsProduct({{256}, {1, 2}})
    ->UseRealTime()
    ->ComputeStatistics("min", fastest)
    ->Unit(benchmark::kMillisecond);

} // namespace
} // namespace clothtear::bench

BENCHMARK_MAIN();
