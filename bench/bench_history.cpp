// Google Benchmark cases for rewind and undo (include/clothtear/history.h), issue 14.
//
//   BM_HistoryRecord/RES/MOTION   one checkpoint of the curtain after each frame (the frame's step
//                                 untimed): MOTION 0 hangs at rest (sleep off), 1 swings (an impulse
//                                 every second), 2 tears (a heavy ball through it). Counters:
//                                 bytes_per_frame and MB_per_s of history (60 frames a second), and
//                                 step_ms, the frame it records, for scale.
//   BM_HistoryRestore/RES         putting a checkpoint back into a World (an undo, a scrub)
//
// Recommended: clothtear_bench --benchmark_filter=History --benchmark_repetitions=5
//              --benchmark_report_aggregates_only=true
#include "bench_scene.h"

#include "clothtear/history.h"

#include <benchmark/benchmark.h>

#include <chrono>

namespace clothtear::bench {
namespace {

World moving(int res, int motion) {
    World w = settledCurtain({res, true});
    w.settings.sleep.enabled = false;
    if (motion == 2) {
        Ball b;
        b.x = Vec3(0, 0, 1.2f);
        b.v = Vec3(0, 0, -10);
        b.radius = 0.3f;
        b.mass = 40;
        w.balls.push_back(b);
    }
    return w;
}

void BM_HistoryRecord(benchmark::State& state) {
    const int res = int(state.range(0)), motion = int(state.range(1));
    World w = moving(res, motion);
    HistoryLimits unlimited;
    unlimited.seconds = 1e9;
    unlimited.bytes = ~size_t(0);
    History history(unlimited);
    history.record(w);
    const size_t first = history.bytes();
    double stepMs = 0;
    uint64_t frames = 0;
    for (auto _ : state) {
        state.PauseTiming();
        if (motion == 1 && w.steps % 60 == 0) w.applyImpulse(Vec3(0, 0, 0), 10.f, Vec3(0, 0, 1), 1.f);
        const auto t0 = std::chrono::steady_clock::now();
        w.step();
        stepMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        ++frames;
        state.ResumeTiming();
        history.record(w);
    }
    const double perFrame = frames ? double(history.bytes() - first) / double(frames) : 0.0;
    state.counters["bytes_per_frame"] = perFrame;
    state.counters["MB_per_s"] = perFrame / w.settings.time.frameDt / 1e6;
    state.counters["first_MB"] = double(first) / 1e6;
    state.counters["step_ms"] = frames ? stepMs / double(frames) : 0.0;
    state.counters["tears"] = double(w.tearLog.total());
}

void BM_HistoryRestore(benchmark::State& state) {
    World w = moving(int(state.range(0)), 1);
    History history;
    for (int f = 0; f < 10; ++f) history.record(w), w.step();
    World target = w;
    for (auto _ : state) {
        history.at(0).restore(target);
        benchmark::ClobberMemory();
    }
}

} // namespace

BENCHMARK(BM_HistoryRecord)
    ->ArgsProduct({{64, 128}, {0, 1, 2}})
    ->ArgNames({"res", "motion"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(120)
    ->UseRealTime();
BENCHMARK(BM_HistoryRestore)->Arg(64)->Arg(128)->ArgName("res")->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace clothtear::bench
