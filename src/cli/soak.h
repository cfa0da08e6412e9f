// Soak: a long headless run of randomized interaction with tearing (grabs that drag and tear, impulses,
// thrown balls, gusts of wind, rebuilds when the cloth is shredded), printing a line every period with
// memory (RSS), progress, tears and the checks: every value finite (check.finite: phase boundaries)
// and every topology invariant (validateCloth). `clothtear_soak` runs it; README "Robustness".
#pragma once
#include <cstdint>
#include <iosfwd>
#include <string>

namespace clothtear {

struct SoakOptions {
    double minutes = 60;       // wall-clock length
    int resolution = 128;      // particles a side
    uint64_t seed = 1;         // the interaction is the same for the same seed and thread count
    double reportSeconds = 60; // wall-clock seconds between lines
    long maxFrames = -1;       // stop after this many frames (tests); -1: run for `minutes`
};

struct SoakResult {
    long frames = 0;
    uint64_t tears = 0; // over all rebuilds
    int rebuilds = 0;   // fresh cloths after the first
    uint64_t grabs = 0, impulses = 0, balls = 0;
    double rssStartMiB = 0, rssEndMiB = 0, rssMaxMiB = 0;
    std::string failure; // "" or the first non-finite value / broken invariant
    bool ok() const { return failure.empty(); }
};

SoakResult runSoak(const SoakOptions& options, std::ostream& log);

// Resident set size of this process in MiB (/proc/self/status), 0 where unknown.
double residentMiB();

} // namespace clothtear
