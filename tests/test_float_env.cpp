// The step flushes subnormal numbers (src/core/step/float_env.h) and leaves the caller's
// floating-point environment as it found it.
#include "clothtear/scenes.h"
#include "omp_threads.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace clothtear;

namespace {

constexpr float kSubnormal = 1e-39f; // below FLT_MIN (1.18e-38)

// Is a * b, computed here at run time, subnormal? (It is in the default environment.)
bool productIsSubnormal(float a, float b) {
    volatile float x = a, y = b;
    return std::fpclassify(x * y) == FP_SUBNORMAL;
}

// A 65 x 65 curtain (enough particles for parallelRegion to fork) whose free particles sit a
// subnormal distance out of their plane and drift out of it at a subnormal speed: what the damping
// leaves of a hand's or a ball's push sideways.
World curtainWithSubnormalOffsets() {
    World w;
    const std::vector<std::string> sets{"cloth.resolution_x=65", "cloth.resolution_y=65"};
    EXPECT_EQ(loadScene(w, "curtain", sets), "");
    for (Index p = 0; p < w.cloth.particleCount(); ++p)
        if (w.cloth.invMass[p] > 0.f) {
            w.cloth.x[p].z() = kSubnormal;
            w.cloth.v[p].z() = kSubnormal;
        }
    return w;
}

size_t subnormalComponentsOfFreeParticles(const World& w) {
    size_t count = 0;
    for (Index p = 0; p < w.cloth.particleCount(); ++p) {
        if (w.cloth.invMass[p] == 0.f) continue;
        for (int c = 0; c < 3; ++c)
            for (float value : {w.cloth.x[p][c], w.cloth.v[p][c]}) count += std::fpclassify(value) == FP_SUBNORMAL;
    }
    return count;
}

class FloatEnvThreads : public ::testing::TestWithParam<int> {};

} // namespace

// Without the flush, x.z + v.z dt stays subnormal (nothing else acts along z in a flat curtain) and
// every free particle keeps two subnormal components.
TEST_P(FloatEnvThreads, TheStepLeavesNoSubnormalPositionOrVelocityOnAFreeParticle) {
    const test::OmpThreads threads(GetParam());
    World w = curtainWithSubnormalOffsets();
    ASSERT_GT(subnormalComponentsOfFreeParticles(w), size_t(8000));
    w.step();
    EXPECT_EQ(subnormalComponentsOfFreeParticles(w), size_t(0));
    EXPECT_TRUE(w.finite);
}

INSTANTIATE_TEST_SUITE_P(Threads, FloatEnvThreads, ::testing::Values(1, 2));

// The flush is the step's alone: after World::step and World::substep the caller's thread, and the
// OpenMP threads the step used, compute subnormal results again.
TEST(FloatEnv, TheCallersEnvironmentIsRestoredOnEveryThread) {
    ASSERT_TRUE(productIsSubnormal(1e-30f, 1e-10f));
    const test::OmpThreads threads(2);
    World w = curtainWithSubnormalOffsets();
    w.step();
    w.substep();
    EXPECT_TRUE(productIsSubnormal(1e-30f, 1e-10f));
#if CLOTHTEAR_HAVE_OPENMP
    int subnormalOnEveryThread = 1;
#pragma omp parallel num_threads(2) reduction(& : subnormalOnEveryThread)
    subnormalOnEveryThread &= productIsSubnormal(1e-30f, 1e-10f) ? 1 : 0;
    EXPECT_EQ(subnormalOnEveryThread, 1);
#endif
}
