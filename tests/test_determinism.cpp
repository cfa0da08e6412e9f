// Determinism: the same scene, parameters and interaction give a bit-identical state (stateHash)
// run after run, single-threaded and multi-threaded. These compare a run with itself; the pinned
// golden hashes that detect a changed result are in test_golden_hash.cpp.
//
// The hash depends on the thread count: each thread sums its springs' forces and limit corrections
// into its own buffer and the buffers are added in thread order, so 1 and 2 threads add the same
// floats in a different order (see parallel.h). Runs with the same thread count are bit-identical,
// because the split of the work is fixed by the thread count, never by timing.
#include "clothtear/scenes.h"
#include "clothtear/state_hash.h"
#include "clothtear/tear.h"
#include "omp_threads.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace clothtear;

namespace {

// Runs `scene` for `frames` with `threads` OpenMP threads; between frames a fixed interaction (an
// impulse every 7 frames, a thrown ball at frame 20) stands in for a person, the same every run.
uint64_t runHash(const char* scene, const std::vector<std::string>& sets, int frames, int threads) {
    const test::OmpThreads scope(threads);
    World w;
    EXPECT_EQ(loadScene(w, scene, sets), "");
    for (int f = 0; f < frames; ++f) {
        if (f % 7 == 3)
            w.applyImpulse(w.cloth.x[w.cloth.particleCount() / 2], 0.4f, Vec3(0.f, 0.f, 1.f), 2.f);
        if (f == 20) {
            Ball b;
            b.radius = 0.3f;
            b.mass = 5.f;
            b.x = Vec3(0.5f, 0.f, 1.f);
            b.v = Vec3(0.f, 0.f, -8.f);
            w.balls.push_back(b);
        }
        w.step();
    }
    EXPECT_TRUE(w.finite) << scene << ": " << w.nonFiniteWhere;
    return stateHash(w);
}

struct Case {
    const char* scene;
    std::vector<std::string> sets;
    int frames;
};

// Above 2048 particles the step uses every thread (step_context.cpp threadsFor); these cloths are above it.
const Case kCases[] = {
    {"tension", {"tension.notch=1"}, 90},                                  // drivers, tearing, 2304 particles
    {"ball-r1-v3-high", {}, 60},                                           // ball, collisions, tearing
    {"flag", {"cloth.resolution_x=64", "cloth.resolution_y=40"}, 40},      // wind
    {"irregular", {"cloth.resolution_x=50", "cloth.resolution_y=50"}, 40}, // irregular mesh, ground
    // A hand pulling until the sheet tears: the limit's Gauss-Seidel passes on lists of a few hundred
    // springs, split by region over the threads (limit.cpp, regionPasses). A listing that wrote
    // back a flag another thread had just set (expand) made 2 of 4 such runs differ.
    {"pull", {"cloth.resolution_x=60", "cloth.resolution_y=60"}, 90},
};

} // namespace

// Repeatability, not correctness: the same run twice in one process gives the same state hash, so
// nothing in the step depends on timing, uninitialized memory, addresses or leftover state. Both
// runs execute the same code, so a wrong change to the step passes this; the golden hashes
// (Determinism.GoldenHashesAreUnchanged, test_golden_hash.cpp) are what catch a change.
TEST(Determinism, SameRunSameHashSingleThreaded) {
    for (const Case& c : kCases) {
        const uint64_t a = runHash(c.scene, c.sets, c.frames, 1), b = runHash(c.scene, c.sets, c.frames, 1);
        EXPECT_EQ(hashHex(a), hashHex(b)) << c.scene;
    }
}

// The same with two threads: the split of the work is fixed by the thread count, never by timing,
// so two threads repeat too (their hash differs from one thread's; see the top of this file).
TEST(Determinism, SameRunSameHashMultiThreaded) {
    for (int threads : {2})
        for (const Case& c : kCases) {
            const uint64_t a = runHash(c.scene, c.sets, c.frames, threads);
            const uint64_t b = runHash(c.scene, c.sets, c.frames, threads);
            EXPECT_EQ(hashHex(a), hashHex(b)) << c.scene << " with " << threads << " threads";
        }
}

// The hash must see every part of the state it claims to cover, or equal hashes prove nothing.
TEST(Determinism, HashSeesOneUlpOfVelocityATearABallAndTime) {
    World w;
    ASSERT_EQ(
        loadScene(w, "curtain", std::vector<std::string>{"cloth.resolution_x=10", "cloth.resolution_y=10"}),
        "");
    w.step();
    const uint64_t h0 = stateHash(w);
    EXPECT_EQ(stateHash(w), h0);
    World v = w;
    v.cloth.v[42].x() = std::nextafter(v.cloth.v[42].x(), 1e9f);
    EXPECT_NE(stateHash(v), h0);
    World t = w;
    TearContext ctx{t.settings.tear, 0.0, nullptr};
    ASSERT_TRUE(forceTear(t.cloth, 30, ctx));
    EXPECT_NE(stateHash(t), h0);
    World b = w;
    b.balls.push_back(Ball{});
    EXPECT_NE(stateHash(b), h0);
    World s = w;
    s.step();
    EXPECT_NE(stateHash(s), h0);
    EXPECT_EQ(hashHex(0x0123456789abcdefull), "0x0123456789abcdef");
}
