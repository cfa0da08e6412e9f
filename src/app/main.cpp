// `clothtear` with the desktop app: opens the window, or runs headless with --headless.
#include "app.h"
#include "cli/runner.h"

int main(int argc, char** argv) {
    clothtear::CliOptions options;
    if (int status = clothtear::parseCommandLine(argc, argv, options, /*appAvailable=*/true); status >= 0)
        return status;
    if (options.headless) return clothtear::runHeadless(options);
    clothtear::app::App app;
    return app.run(options);
}
