// The spring groups (src/core/step/spring_groups.h): springs in groups of eight evenly spaced ones,
// their forces from plain vector loads. They must give the forces of the generic loop (up to the
// order of additions), and the SSE2 and AVX2 kernels the same bits, on a torn cloth too.
#include "clothtear/scenes.h"
#include "clothtear/state_hash.h"
#include "clothtear/world.h"
#include "clothtear/world_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

namespace clothtear {
namespace {

// An environment switch of the spring cache (CLOTHTEAR_SPRING_KERNEL, CLOTHTEAR_MERGE_SPRINGS) for
// the worlds loaded while it lives (the cache reads it when it is built, at a loaded world's first
// sub-step).
class EnvScope {
public:
    EnvScope(const char* name, const char* value) : name_(name) { setenv(name, value, 1); }
    ~EnvScope() { unsetenv(name_); }
    EnvScope(const EnvScope&) = delete;
    EnvScope& operator=(const EnvScope&) = delete;

private:
    const char* name_;
};

// The pull scene at 40 a side, pulled at 30 deg in a 2 m/s wind, after 0.75 s: torn (the rip starts
// at 0.69 s and goes on to about 1.26 s), its new particles and springs appended past the grid's, and
// moving in all three directions (without the wind the sheet stays in its plane and every force's
// normal component is exactly 0).
std::string tornPullBytes() {
    World w;
    EXPECT_EQ(loadScene(w, "pull",
                        std::vector<std::string>{"pull.angle=30", "cloth.resolution_x=40", "cloth.resolution_y=40",
                                                 "wind.enabled=1", "wind.speed=2"}),
              "");
    while (w.time < 0.75) w.step();
    EXPECT_GT(w.tearLog.total(), 0u);
    std::string bytes;
    EXPECT_EQ(serializeWorld(w, bytes), "");
    return bytes;
}

World loaded(const std::string& bytes) {
    Result<World> r = parseWorld(bytes, "torn pull");
    EXPECT_TRUE(r.ok()) << r.error;
    return std::move(r.value);
}

bool cpuHasAvx2() {
#if defined(__x86_64__) && defined(__GNUC__)
    return __builtin_cpu_supports("avx2");
#else
    return false;
#endif
}

} // namespace

// One sub-step with only the springs, gravity and air acting (no limit, no tearing): the velocities
// after it with the groups equal those of the generic loop up to rounding, relative to the largest
// velocity change of the sub-step. A spring missed, counted twice or given the wrong ends changes a
// velocity by about k x strain x dt / m, a large part of that change.
TEST(SpringGroups, GroupedKernelsGiveTheForcesOfTheGenericLoop) {
    const std::string bytes = tornPullBytes();
    auto oneSubStep = [&](const char* kernel) {
        EnvScope scope("CLOTHTEAR_SPRING_KERNEL", kernel);
        World w = loaded(bytes);
        w.settings.limit.enabled = false;
        w.settings.tear.enabled = false;
        w.substep();
        return w;
    };
    const World before = loaded(bytes);
    const World generic = oneSubStep("generic");
    EXPECT_EQ(generic.profile.groupedSprings, 0u);
    EXPECT_STREQ(generic.profile.springKernel, "generic");
    float largestChange = 0.f;
    for (size_t p = 0; p < generic.cloth.particleCount(); ++p)
        largestChange = std::max(largestChange, (generic.cloth.v[p] - before.cloth.v[p]).norm());
    ASSERT_GT(largestChange, 1e-3f);
    for (const char* kernel : {"sse2", "avx2"}) {
        const World grouped = oneSubStep(kernel);
        const size_t springs = grouped.cloth.springs.size() + grouped.cloth.bends.size();
        // The torn grid still runs most of its springs in groups (not the tear's new springs, nor
        // those along the borders that do not fill a group of eight).
        EXPECT_GT(grouped.profile.groupedSprings, springs * 3 / 4) << kernel;
        ASSERT_EQ(grouped.cloth.particleCount(), generic.cloth.particleCount());
        float worst = 0.f;
        for (size_t p = 0; p < grouped.cloth.particleCount(); ++p)
            worst = std::max(worst, (grouped.cloth.v[p] - generic.cloth.v[p]).norm());
        EXPECT_LT(worst, 1e-4f * largestChange) << kernel << ": velocity change up to " << largestChange << " m/s";
    }
}

// The two kernels do the same operations lane by lane (no fused multiply-add) and add into the same
// floats in the same order, so a run with tearing, the limit and everything else on is the same to
// the bit: the state hash after 0.5 s more of the torn pull, in which it tears again.
TEST(SpringGroups, SseAndAvxKernelsGiveTheSameBits) {
    if (!cpuHasAvx2()) GTEST_SKIP() << "no AVX2 on this CPU: both would run the SSE2 kernel";
    const std::string bytes = tornPullBytes();
    auto run = [&](const char* kernel) {
        EnvScope scope("CLOTHTEAR_SPRING_KERNEL", kernel);
        World w = loaded(bytes);
        const double end = w.time + 0.5;
        while (w.time < end) w.step();
        EXPECT_STREQ(w.profile.springKernel, kernel);
        return w;
    };
    const World sse = run("sse2"), avx = run("avx2");
    EXPECT_GT(avx.tearLog.total(), loaded(bytes).tearLog.total()) << "the tear goes on in the time compared";
    EXPECT_EQ(stateHash(sse), stateHash(avx));
}


// Bend-shear springs with the same ends and rest length share one entry of the spring cache, their
// stiffness and damping summed (springs.cpp). One sub-step with only the springs, gravity and air
// acting, with and without the merge: the same velocities up to rounding, relative to the sub-step's
// largest velocity change from the bend-shear springs alone (a copy left out, or counted twice,
// changes a velocity by its force, about as much as that). On the grid of n x n particles the
// bend-shear springs that span two columns or two rows come twice (two edges whose opposite corners
// are the same two particles): (n - 2)^2 of them are merged. On the torn pull sheet (new particles
// and springs past the grid's) and on the irregular mesh, whose twins can differ in weight, the same.
TEST(SpringGroups, MergedBendShearTwinsGiveTheForcesOfBoth) {
    struct Case {
        const char* what;
        std::string bytes;
        long gridSide; // 0: not a whole grid
    };
    auto bytesOf = [](const char* scene, std::vector<std::string> sets) {
        World w;
        EXPECT_EQ(loadScene(w, scene, sets), "");
        for (int f = 0; f < 20; ++f) w.step(); // swinging in the wind: the bend-shear springs bent
        std::string bytes;
        EXPECT_EQ(serializeWorld(w, bytes), "");
        return bytes;
    };
    const Case cases[] = {
        {"curtain 24", bytesOf("curtain", {"cloth.resolution_x=24", "cloth.resolution_y=24", "wind.enabled=1"}), 24},
        {"irregular 20", bytesOf("irregular", {"cloth.resolution_x=20", "cloth.resolution_y=20", "wind.enabled=1"}), 0},
        {"torn pull 40", tornPullBytes(), 0},
    };
    for (const Case& c : cases) {
        auto oneSubStep = [&](bool merge, float bendScale) {
            EnvScope scope("CLOTHTEAR_MERGE_SPRINGS", merge ? "1" : "0");
            World w = loaded(c.bytes);
            w.settings.limit.enabled = false;
            w.settings.tear.enabled = false;
            w.settings.material.bendStiffness *= bendScale;
            w.settings.material.bendDamping *= bendScale;
            w.substep();
            return w;
        };
        const World separate = oneSubStep(false, 1.f), merged = oneSubStep(true, 1.f);
        const World withoutBends = oneSubStep(false, 0.f);
        EXPECT_EQ(separate.profile.mergedSprings, 0u) << c.what;
        if (c.gridSide) {
            EXPECT_EQ(long(merged.profile.mergedSprings), (c.gridSide - 2) * (c.gridSide - 2)) << c.what;
        } else {
            EXPECT_GT(merged.profile.mergedSprings, 0u) << c.what;
        }
        float bendChange = 0.f, worst = 0.f;
        for (size_t p = 0; p < separate.cloth.particleCount(); ++p) {
            bendChange = std::max(bendChange, (separate.cloth.v[p] - withoutBends.cloth.v[p]).norm());
            worst = std::max(worst, (merged.cloth.v[p] - separate.cloth.v[p]).norm());
        }
        ASSERT_GT(bendChange, 0.f) << c.what;
        EXPECT_LT(worst, 1e-3f * bendChange) << c.what << ": the bend-shear springs change a velocity by up to "
                                             << bendChange << " m/s";
    }
}

} // namespace clothtear
