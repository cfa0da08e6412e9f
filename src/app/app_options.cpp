// The window app's options (app_options.h), registered on the shared parser of run_options.h.
#include "app_options.h"

#include <CLI/CLI.hpp>

namespace clothtear::app {

int parseAppOptions(int argc, char** argv, AppOptions& o) {
    RunOptionsExtension extension;
    extension.add = [&o](CLI::App& cli) {
        cli.add_option("--frames", o.frames, "App: run N frames, then exit")->check(CLI::Number)->check(CLI::Range(0, 100000000));
        cli.add_option("--screenshot", o.screenshot, "App: write a PNG of the last frame to FILE");
        cli.add_option("--script", o.script, "App: replay an input script");
        cli.add_option("--record", o.record, "App: record input to a script file");
    };
    // The window's options mean nothing without a window: refuse them rather than ignore them.
    extension.check = [](const CLI::App& cli, const RunOptions& run) -> std::string {
        if (run.headless)
            for (const char* option : {"--frames", "--screenshot", "--script", "--record"})
                if (cli.count(option))
                    return std::string(option) + " needs the window app; drop --headless (no display: "
                                                  "xvfb-run -a clothtear ...)";
        return {};
    };
    return parseRunOptions(argc, argv, o, extension);
}

} // namespace clothtear::app
