// clothbench: the measurements behind "fast and accurate" (bench/README.md), headless, writing CSV
// and SVG into one folder.
//
//   clothbench --mode MODE [--out DIR] [--quick] [--threads N] [--seed S] [--stress-seconds T]
//
// Modes: accuracy (run time against error, convergence orders), stability (largest stable step
// against stiffness and density), static (equilibrium against the static solve, mesh refinement),
// skipping (per-phase timings, what skipping, sleeping and the ball broad phase save), stress (a
// long randomized tearing run: invariants and memory), peers (Bullet soft-body cloth, memory
// bandwidth bound), holds (issue 12: does the cloth hold at every size, resolution, pin and load;
// holds.cpp), vacuum (issue 16: Tagawa 2003's experiments in vacuum, both material models against
// the measured curves; vacuum.cpp), all (every mode but stress, holds and vacuum).
#include "common.h"
#include "run_options.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <unistd.h>
#if CLOTHTEAR_HAVE_OPENMP
#include <omp.h>
#endif

namespace clothtear::bench {

void setThreads(int threads) {
#if CLOTHTEAR_HAVE_OPENMP
    omp_set_num_threads(threads);
#else
    (void)threads;
#endif
}

std::string machineDescription() {
    std::string model = "unknown CPU";
    std::ifstream cpu("/proc/cpuinfo");
    for (std::string line; std::getline(cpu, line);)
        if (line.rfind("model name", 0) == 0) {
            model = line.substr(line.find(':') + 2);
            break;
        }
    double load[3] = {0, 0, 0};
    if (getloadavg(load, 3) < 0)
        load[0] = -1;
    char buf[256];
    std::snprintf(buf, sizeof buf, "%s, %ld logical CPUs, load average %.2f", model.c_str(),
                  sysconf(_SC_NPROCESSORS_ONLN), load[0]);
    return buf;
}

size_t residentBytes() {
    std::ifstream f("/proc/self/statm");
    size_t pages = 0, resident = 0;
    if (!(f >> pages >> resident))
        return 0;
    return resident * size_t(sysconf(_SC_PAGESIZE));
}

} // namespace clothtear::bench

int main(int argc, char** argv) {
    using namespace clothtear::bench;
    BenchOptions o;
    std::string mode;
    CLI::App app{
        "clothbench: run time against error, stability, static accuracy, skipping, stress and peers"};
    app.add_option("--mode", mode, "accuracy | stability | static | skipping | stress | peers | holds | vacuum | all")
        ->required()
        ->check(CLI::IsMember({"accuracy", "stability", "static", "skipping", "stress", "peers", "holds", "vacuum", "all"}));
    app.add_option("--out", o.out, "Folder for the CSV and SVG files (created if missing)");
    app.add_flag("--quick", o.quick, "Fewer points and shorter runs (smoke run)");
    app.add_option("--threads", o.threads, "OpenMP threads for the timed runs (peers: both 1 and this)")
        ->check(CLI::Range(1, 64));
    app.add_option("--accuracy-scene", o.accuracyScene, "Accuracy mode: only this scene (swing, curtain, drop, ...)");
    app.add_option("--seed", o.seed, "Stress mode: seed of the random interaction script");
    app.add_option("--stress-seconds", o.stressSeconds,
                   "Stress mode: simulated seconds (the script depends on the seed only)")
        ->check(CLI::Range(0.1, 36000.0));
    app.add_option("--stress-resolution", o.stressResolution, "Stress mode: particles per side")
        ->check(CLI::Range(4, 512));
    app.add_option("--sizes", o.holdsSizes, "Holds mode: cloth sizes in m (default 0.4,2,6)")
        ->delimiter(',')
        ->check(CLI::Range(0.05, 100.0));
    app.add_option("--res", o.holdsRes, "Holds mode: particles a side of the grid table (default 33,65)")
        ->delimiter(',')
        ->check(CLI::Range(3, 1024));
    app.add_flag("--holds-129", o.holds129, "Holds mode: also 129 particles a side (slow)");
    app.add_flag("--holds-257", o.holds257, "Holds mode: also the 2 m cloth at 257 a side (slow)");
    app.add_option("--tables", o.holdsTables, "Holds mode: grid, loaded, sag (comma separated) or all");
    app.add_option("--set", o.sets, "Holds and vacuum modes: KEY=VALUE for every run (repeatable), e.g. limit.solver=xpbd");
    app.add_option("--runs", o.runs, "Vacuum mode: only the runs whose label contains one of these (comma separated), e.g. 'kes forward-euler guard'")
        ->delimiter(',');
    app.add_flag("--reversals", o.reversals, "Vacuum mode: also count the kes hinges' curvature reversals against a threshold (the jitter table)");
    app.add_option("--tag", o.tag, "Holds mode: CSV name suffix (holds_TAG.csv)");
    if (const int status = clothtear::parseCommandLine(app, argc, argv, "clothbench"); status >= 0) return status;
    for (int i = 0; i < argc; ++i)
        o.commandLine += std::string(i ? " " : "") + argv[i];
    std::error_code ec;
    std::filesystem::create_directories(o.out, ec);
    if (ec || !std::filesystem::is_directory(o.out)) {
        std::cerr << "clothbench: cannot create output folder '" << o.out << "'\n";
        return 2;
    }
    const std::map<std::string, int (*)(const BenchOptions&)> modes = {
        {"accuracy", runAccuracy}, {"stability", runStability}, {"static", runStatic},
        {"skipping", runSkipping}, {"stress", runStress},       {"peers", runPeers},
        {"holds", runHolds},       {"vacuum", runVacuum}};
    std::cout << "clothbench: " << o.commandLine << "\nmachine: " << machineDescription() << "\n";
    try {
        if (mode != "all")
            return modes.at(mode)(o);
        int status = 0;
        for (const char* m : {"accuracy", "stability", "static", "skipping", "peers"})
            status |= modes.at(m)(o);
        return status;
    } catch (const std::exception& e) {
        std::cerr << "clothbench: " << e.what() << "\n";
        return 1;
    }
}
