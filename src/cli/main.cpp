// `clothtear` built without the app: the headless runner only.
#include "runner.h"

#include <iostream>

int main(int argc, char** argv) {
    clothtear::CliOptions options;
    if (int status = clothtear::parseCommandLine(argc, argv, options, false); status >= 0) return status;
    if (!options.headless) {
        std::cerr << "clothtear: this build has no window app (CLOTHTEAR_BUILD_APP=OFF); use --headless\n";
        return 2;
    }
    return clothtear::runHeadless(options);
}
