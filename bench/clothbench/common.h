// Shared by the clothbench modes: options, loading scenes, timing, the thread count.
#pragma once
#include "clothtear/scenes.h"
#include "clothtear/world.h"

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace clothtear::bench {

struct BenchOptions {
    std::string out = "bench-out"; // folder for CSV and SVG files
    bool quick = false;            // fewer points and shorter runs (a smoke run, minutes instead of tens)
    uint64_t seed = 1;             // stress mode: the random script
    double stressSeconds = 120;    // stress mode: simulated seconds of the randomized run
    int stressResolution = 128;    // stress mode: particles per side
    int threads = 1;               // OpenMP threads for the timed runs of every mode but `peers`
    std::string accuracyScene;     // accuracy mode: only this scene ("" = every scene)
    std::string commandLine;       // how this run was started, written into every plot
    // holds mode (issue 12)
    std::vector<double> holdsSizes; // m, cloth sizes of the grid table ({} = 0.4, 2, 6)
    std::vector<int> holdsRes;      // particles a side of the grid table ({} = 33, 65)
    bool holds129 = false;          // grid table: also 129 a side (slow)
    bool holds257 = false;          // grid table: also the 2 m cloth at 257 a side (slow)
    std::string holdsTables = "all"; // grid, loaded, sag (any of them, comma separated) or all
    std::vector<std::string> sets;  // KEY=VALUE applied to every run of the mode (a candidate solver)
    std::string tag;                // suffix of the CSV file name (holds_TAG.csv)
    // vacuum mode (issue 16)
    std::vector<std::string> runs;  // only the runs whose label contains one of these ({} = all)
    bool reversals = false;         // also the table of the hinges' curvature reversals (jitter)
};

// Loads a scene with overrides; a bad name or override is a bug in clothbench itself, so it throws
// (main prints it and exits non-zero).
inline World loadOrThrow(const std::string& scene, const std::vector<std::string>& overrides) {
    World w;
    if (std::string err = loadScene(w, scene, overrides); !err.empty())
        throw std::runtime_error("scene '" + scene + "': " + err);
    return w;
}

// A number as --set accepts it, with all its digits (std::to_string keeps six decimals only).
inline std::string num(double v) {
    char b[40];
    std::snprintf(b, sizeof b, "%.9g", v);
    return b;
}

inline double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Sets the OpenMP thread count (no-op without OpenMP).
void setThreads(int threads);

// The machine, in one line (CPU model, logical CPUs, load average) for the notes of every output.
std::string machineDescription();

// Resident set size of this process in bytes (from /proc/self/statm), 0 where unavailable.
size_t residentBytes();

// Each mode: writes its CSV/SVG files into options.out and prints a summary. Returns an exit status.
int runAccuracy(const BenchOptions& options);
int runStability(const BenchOptions& options);
int runStatic(const BenchOptions& options);
int runSkipping(const BenchOptions& options);
int runStress(const BenchOptions& options);
int runPeers(const BenchOptions& options);
int runHolds(const BenchOptions& options);
int runVacuum(const BenchOptions& options);

} // namespace clothtear::bench
