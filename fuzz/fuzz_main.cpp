// libFuzzer entry point of one harness (CLOTHTEAR_FUZZ_HARNESS, set per executable in CMakeLists.txt):
// any violation found is printed and aborts, which libFuzzer reports as a crash and saves the input.
#include "harness.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string problem =
        clothtear::fuzz::CLOTHTEAR_FUZZ_HARNESS(std::string_view(reinterpret_cast<const char*>(data), size));
    if (!problem.empty()) {
        std::fprintf(stderr, "clothtear fuzz: %s\n", problem.c_str());
        std::abort();
    }
    return 0;
}
