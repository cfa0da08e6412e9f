// clothtear_soak: the one-hour headless soak (src/cli/soak.h). Exit status 0 when every check held,
// 1 on a non-finite value or a broken invariant, 2 on bad options.
#include "run_options.h"
#include "soak.h"

#include <CLI/CLI.hpp>
#include <iostream>

int main(int argc, char** argv) {
    clothtear::SoakOptions o;
    CLI::App app{"clothtear_soak: randomized interaction with tearing, with memory and invariant checks"};
    app.add_option("--minutes", o.minutes, "Wall-clock length")->check(CLI::Range(0.0, 1e6));
    app.add_option("--resolution", o.resolution, "Particles a side")->check(CLI::Range(4, 1024));
    app.add_option("--seed", o.seed, "Seed of the interaction");
    app.add_option("--report-every", o.reportSeconds, "Wall-clock seconds between lines")
        ->check(CLI::Range(0.1, 1e6));
    app.add_option("--frames", o.maxFrames, "Stop after N frames instead")
        ->check(CLI::Range(0L, 1000000000L));
    if (const int status = clothtear::parseCommandLine(app, argc, argv, "clothtear_soak"); status >= 0) return status;
    const clothtear::SoakResult r = clothtear::runSoak(o, std::cout);
    std::cout << "soak: " << r.frames << " frames, " << r.tears << " tears, " << r.rebuilds << " rebuilds, "
              << r.grabs << " grabs, " << r.impulses << " impulses, " << r.balls << " balls; RSS start "
              << r.rssStartMiB << " MiB, end " << r.rssEndMiB << " MiB, max " << r.rssMaxMiB << " MiB; "
              << (r.ok() ? "every check held" : "FAILED: " + r.failure) << "\n";
    return r.ok() ? 0 : 1;
}
