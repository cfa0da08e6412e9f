#include "raster_priority.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#if defined(__linux__)
#include <dirent.h>
#include <sys/resource.h>
#include <sys/types.h>
#endif

namespace clothtear::app {

RasterYield yieldSoftwareRaster(int niceness) {
    RasterYield out;
    if (niceness <= 0) return out;
#if defined(__linux__)
    DIR* tasks = opendir("/proc/self/task");
    if (!tasks) {
        out.error = std::string("cannot list this process's threads (/proc/self/task: ") + std::strerror(errno) +
                    ")";
        return out;
    }
    while (const dirent* entry = readdir(tasks)) {
        char* end = nullptr;
        const long tid = std::strtol(entry->d_name, &end, 10);
        if (tid <= 0 || *end) continue;
        std::ifstream comm(std::string("/proc/self/task/") + entry->d_name + "/comm");
        std::string name;
        if (!std::getline(comm, name) || name.rfind("llvmpipe-", 0) != 0) continue;
        // A thread's nice value is its own on Linux: PRIO_PROCESS with a thread id sets that one.
        if (setpriority(PRIO_PROCESS, id_t(tid), niceness) == 0) {
            ++out.threads;
            out.niceness = niceness;
        } else if (out.error.empty()) {
            out.error = "cannot lower raster thread " + name + " (" + std::strerror(errno) + ")";
        }
    }
    closedir(tasks);
#endif
    return out;
}

RasterNiceness rasterNicenessFromEnv(int fallback) {
    RasterNiceness out{fallback, {}};
    const char* set = std::getenv("CLOTHTEAR_RASTER_NICE");
    if (!set) return out;
    char* end = nullptr;
    errno = 0;
    const long n = std::strtol(set, &end, 10);
    if (!*set || *end || errno || n < 0 || n > 19)
        out.error = std::string("CLOTHTEAR_RASTER_NICE=") + set + " is not a nice value from 0 to 19; using " +
                    std::to_string(fallback);
    else
        out.value = int(n);
    return out;
}

} // namespace clothtear::app
