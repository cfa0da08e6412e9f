// Golden state hashes: fixed runs whose exact state_hash after a fixed number of frames is pinned
// here. A comparison of two runs of today's code (test_determinism.cpp) cannot see a change that
// alters both; these can. A restructure that claims "behaviour unchanged" keeps every value below.
//
// When a change is meant to alter the physics (or what the hash covers), re-pin in the same commit
// and say why in its message: run with CLOTHTEAR_PRINT_GOLDEN=1 to print the new values.
//
// One thread: the hash depends on the thread count (test_determinism.cpp says why). Release builds
// of g++ on x86-64 (SSE2, no FMA contraction); a different compiler or target may round differently,
// so the values are checked only where they were taken (CLOTHTEAR_GOLDEN_CHECK, tests/CMakeLists.txt).
// The spring groups' SSE2 and AVX2 kernels give the same bits (test_spring_groups.cpp): the values
// hold with or without AVX2.
#include "clothtear/scenes.h"
#include "clothtear/state_hash.h"
#include "omp_threads.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstdio>

using namespace clothtear;

namespace {

struct GoldenCase {
    const char* name;
    const char* scene;
    std::vector<std::string> sets;
    int frames;
    bool interact; // impulses every 9 frames from frame 4 (wakes the cloth, moves it off rest)
    const char* hash;
};

// Small cloths and few frames: the whole test takes about a second.
const GoldenCase kGolden[] = {
    {"curtain", "curtain", {"cloth.resolution_x=24", "cloth.resolution_y=24"}, 60, true, "0x64306752d3f4361b"},
    {"flag", "flag", {"cloth.resolution_x=24", "cloth.resolution_y=16"}, 60, false, "0x192fa1771b7595a5"},
    {"drop", "drop", {"cloth.resolution_x=24", "cloth.resolution_y=24"}, 60, false, "0x0240b855e4900ecc"},
    {"irregular", "irregular", {"cloth.resolution_x=20", "cloth.resolution_y=20"}, 60, true, "0x788fbd8199f055ec"},
    {"tension-notch", "tension", {"tension.notch=1", "cloth.resolution_x=32", "cloth.resolution_y=32"}, 90, false,
     "0xbe0bf45bab2a4d7e"},
    {"ball", "ball-r1-v3-high", {"cloth.resolution_x=32", "cloth.resolution_y=32"}, 60, false, "0x799819f6a7ee2cb5"},
    {"verlet", "curtain", {"cloth.resolution_x=20", "cloth.resolution_y=20", "time.integrator=verlet"}, 60, true,
     "0xd950aa0b713eebe1"},
    {"implicit", "curtain", {"cloth.resolution_x=12", "cloth.resolution_y=12", "time.integrator=implicit-euler"}, 30,
     true, "0xdbabcd036a50c7e3"},
    {"xpbd", "curtain", {"cloth.resolution_x=16", "cloth.resolution_y=16", "time.integrator=xpbd"}, 40, true,
     "0xdefbd7f4d5b80f31"},
    {"pull", "pull", {"cloth.resolution_x=24", "cloth.resolution_y=24", "pull.angle=30"}, 90, false,
     "0xb62ea8853607bd7c"},
};

uint64_t runGolden(const GoldenCase& c) {
    World w;
    EXPECT_EQ(loadScene(w, c.scene, c.sets), "") << c.name;
    for (int f = 0; f < c.frames; ++f) {
        if (c.interact && f % 9 == 4)
            w.applyImpulse(w.cloth.x[w.cloth.particleCount() / 3], 0.5f, Vec3(0.3f, 0.f, 1.f), 1.5f);
        w.step();
    }
    EXPECT_TRUE(w.finite) << c.name << ": " << w.nonFiniteWhere;
    return stateHash(w);
}

} // namespace

TEST(Determinism, GoldenHashesAreUnchanged) {
    const test::OmpThreads oneThread(1);
    const bool print = std::getenv("CLOTHTEAR_PRINT_GOLDEN") != nullptr;
    for (const GoldenCase& c : kGolden) {
        const std::string got = hashHex(runGolden(c));
        if (print) std::printf("    {\"%s\", ...}: \"%s\"\n", c.name, got.c_str());
#if CLOTHTEAR_GOLDEN_CHECK
        EXPECT_EQ(got, c.hash) << c.name << " (scene " << c.scene << ", " << c.frames << " frames)";
#endif
    }
}
