// `clothtear` built without the app: the headless runner only. It knows the shared run options alone
// (run_options.h), so --help lists no window options and CLI11 refuses them as unknown.
#include "run_options.h"
#include "runner.h"

#include <iostream>

int main(int argc, char** argv) {
    clothtear::RunOptions options;
    if (int status = clothtear::parseRunOptions(argc, argv, options); status >= 0) return status;
    if (!options.headless) {
        std::cerr << "clothtear: this build has no window app (CLOTHTEAR_BUILD_APP=OFF); use --headless\n";
        return 2;
    }
    return clothtear::runHeadless(options);
}
