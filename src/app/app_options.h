// The window app's command line: the shared run options (run_options.h) plus what only a window does.
// The headless runner never sees these; `clothtear --headless` with one of them is refused.
#pragma once
#include "run_options.h"

#include <string>

namespace clothtear::app {

struct AppOptions : RunOptions {
    int frames = -1;        // --frames N: run N frames, then exit (-1: until the window closes)
    std::string screenshot; // --screenshot FILE: a PNG of the last frame
    std::string script;     // --script FILE: replay an input script (src/input/input_script.h)
    std::string record;     // --record FILE: record the input to a script
    // --no-pipeline: step, then draw what was stepped, one after the other, instead of stepping the
    // frame while the frame before it is drawn (app.cpp [FRAME], sim_thread.h)
    bool noPipeline = false;
};

// parseRunOptions with the app's options added. Returns -1 to go on, or an exit status (0 after
// --help, --version and the lists, 2 on bad input with one line on stderr).
int parseAppOptions(int argc, char** argv, AppOptions& options);

} // namespace clothtear::app
