// The software rasterizer's threads yield to the simulation (issue 15 goal 5).
//
// Under Mesa's llvmpipe (Xvfb, a machine without a GPU) the raster work of the buffer swap runs on
// CPU threads the driver starts with the context ("llvmpipe-0", "llvmpipe-1", ...), one per core.
// With the pipeline (app.cpp, "the pipeline") the simulation thread steps while the main thread
// draws and swaps, so on two cores the two raster threads and the simulation share them: the
// scheduler time-slices the simulation with a raster thread in 4 ms turns while the other core
// idles for the next job, and a frame bound by its steps waits on those turns. Measured on the
// 2-core VM (`perf sched`, the drag `tear.txt` at 128 a side): the simulation thread ran 74 % of
// the wall time, the CPUs idle 18 %. With the raster threads at a lower priority (nice) they take
// the cores the simulation and the main thread leave, and a frame bound by its swap (a cloth at
// rest, nothing to step) still has both cores for them.
#pragma once
#include <string>

namespace clothtear::app {

struct RasterYield {
    int threads = 0;   // raster threads lowered
    int niceness = 0;  // the nice value they got (0: left alone)
    std::string error; // why none was lowered, if one should have been
};

// Gives the calling process's software raster threads (llvmpipe's) the nice value `niceness`
// (1..19; 0 leaves them alone). Call after the GL context exists (the driver starts them with it).
// Linux only (it reads /proc/self/task); elsewhere, and with a hardware driver, nothing to do.
RasterYield yieldSoftwareRaster(int niceness);

// The nice value to give them: CLOTHTEAR_RASTER_NICE=N (0..19; 0 turns it off, for measurements)
// overrides `fallback`. A value that is not a whole number in 0..19 keeps `fallback` and says so in
// `error`.
struct RasterNiceness {
    int value = 0;
    std::string error;
};
RasterNiceness rasterNicenessFromEnv(int fallback);

} // namespace clothtear::app
