// Switches for tests and benchmarks that compare an exact shortcut of the step with the long way
// (CLOTHTEAR_LIMIT_SKIPS, CLOTHTEAR_MERGE_SPRINGS), or a parallel order with the one-thread order
// (CLOTHTEAR_LIMIT_REGIONS): on unless the variable is "0". Read where a
// cache is built or a solve starts, never per particle.
#pragma once
#include <cstdlib>
#include <cstring>

namespace clothtear {

inline bool envSwitchOn(const char* name) {
    const char* v = std::getenv(name);
    return !(v && std::strcmp(v, "0") == 0);
}

} // namespace clothtear
