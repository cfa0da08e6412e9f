// `clothtear` with the desktop app: opens the window, or runs headless with --headless.
#include "app.h"
#include "app_options.h"
#include "runner.h"

#include <cstdlib>
#include <thread>
#ifdef _OPENMP
#include <omp.h>
#endif

int main(int argc, char** argv) {
    clothtear::app::AppOptions options;
    if (int status = clothtear::app::parseAppOptions(argc, argv, options); status >= 0) return status;
    if (options.headless) return clothtear::runHeadless(options);
#ifdef _OPENMP
    // A software renderer (Mesa's llvmpipe) draws on the CPU cores too. On a machine with two or
    // fewer, a second simulation thread spinning at the step's barriers starves it (64 x 64 under
    // Xvfb: 2 FPS instead of 16 on a loaded 2-core machine), so the window simulates on one thread
    // unless OMP_NUM_THREADS says otherwise.
    if (!std::getenv("OMP_NUM_THREADS") && std::thread::hardware_concurrency() <= 2) omp_set_num_threads(1);
#endif
    clothtear::app::App app;
    return app.run(options);
}
