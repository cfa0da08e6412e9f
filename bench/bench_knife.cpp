// Google Benchmark case for the knife (include/clothtear/knife.h), issue 14.
//
//   BM_KnifeCut/RES   one straight stroke across the settled curtain, top to bottom at u = 0.1 m
//                     (the cut cloth restored, untimed, before each): ms per stroke and, as
//                     ns_per_spring, per spring the stroke cut
//
// Recommended: clothtear_bench --benchmark_filter=Knife --benchmark_repetitions=5
//              --benchmark_report_aggregates_only=true
#include "bench_scene.h"

#include "clothtear/knife.h"

#include <benchmark/benchmark.h>

namespace clothtear::bench {
namespace {

void BM_KnifeCut(benchmark::State& state) {
    const World settled = settledCurtain({int(state.range(0)), true});
    const std::vector<Vec2d> stroke{Vec2d(0.1, 2.0), Vec2d(0.1, -2.0)};
    size_t springs = 0;
    for (auto _ : state) {
        state.PauseTiming();
        World w = settled;
        state.ResumeTiming();
        const CutResult r = w.cut(stroke);
        springs = r.springsCut;
        benchmark::DoNotOptimize(springs);
        state.PauseTiming();
        w = World{}; // freed outside the timing
        state.ResumeTiming();
    }
    state.counters["springs_cut"] = double(springs);
    state.counters["ns_per_spring"] = benchmark::Counter(double(springs), benchmark::Counter::kIsIterationInvariantRate |
                                                                              benchmark::Counter::kInvert);
}

} // namespace

BENCHMARK(BM_KnifeCut)->Arg(64)->Arg(128)->ArgName("res")->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace clothtear::bench
