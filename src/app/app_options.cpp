// The window app's options (app_options.h), registered on the shared parser of run_options.h.
#include "app_options.h"

#include "controls.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <string>

namespace clothtear::app {

int parseAppOptions(int argc, char** argv, AppOptions& o) {
    RunOptionsExtension extension;
    extension.add = [&o](CLI::App& cli) {
        cli.add_option("--frames", o.frames, "App: run N frames, then exit")->check(CLI::Number)->check(CLI::Range(0, 100000000));
        cli.add_option("--screenshot", o.screenshot, "App: write a PNG of the last frame to FILE");
        cli.add_option("--script", o.script, "App: replay an input script");
        cli.add_option("--record", o.record, "App: record input to a script file");
        cli.add_flag("--no-pipeline", o.noPipeline,
                     "App: step the cloth, then draw it, one after the other (by default a frame's steps run "
                     "while the frame before them is drawn: one frame later on screen, faster on few cores)");
        // The keys and mouse, from the table the help overlay (F1) shows.
        std::string keys = "\nIn the window (F1 shows this too):\n";
        for (const ControlHelp& c : controlsHelp()) {
            std::string input = c.input;
            input.resize(std::max<size_t>(input.size(), 20), ' ');
            keys += "  " + input + "  " + c.action + "\n";
        }
        cli.footer(keys);
    };
    // The window's options mean nothing without a window: refuse them rather than ignore them.
    extension.check = [](const CLI::App& cli, const RunOptions& run) -> std::string {
        if (run.headless)
            for (const char* option : {"--frames", "--screenshot", "--script", "--record", "--no-pipeline"})
                if (cli.count(option))
                    return std::string(option) + " needs the window app; drop --headless (no display: "
                                                  "xvfb-run -a clothtear ...)";
        return {};
    };
    return parseRunOptions(argc, argv, o, extension);
}

} // namespace clothtear::app
