// Tearing invariants under random forced tears (all three modes) on grid and irregular meshes.
#include "clothtear/random.h"
#include "clothtear/scenes.h"
#include "clothtear/tear.h"

#include <gtest/gtest.h>

using namespace clothtear;

namespace {

// Samples points of the UV domain and counts the UV triangles that contain each: the torn cloth
// must still tile the original texture exactly once (no area lost, nothing overlapping).
void expectUvTiling(const Cloth& c, Rng& rng, int samples) {
    for (int k = 0; k < samples; ++k) {
        const Vec2d q(rng.uniform(0.001, 0.999), rng.uniform(0.001, 0.999));
        int inside = 0;
        for (const Triangle& t : c.triangles) {
            const double a = uvArea(t.uv[0], t.uv[1], q), b = uvArea(t.uv[1], t.uv[2], q), d = uvArea(t.uv[2], t.uv[0], q);
            if (a >= 0 && b >= 0 && d >= 0) ++inside;
        }
        // A point exactly on a shared edge counts twice; random doubles essentially never land there.
        ASSERT_EQ(inside, 1) << "uv point " << q.transpose() << " covered " << inside << " times";
    }
}

struct RandomTearRun {
    int tears = 0;
    std::array<uint64_t, 3> modes{};
};

RandomTearRun randomTears(World& w, uint64_t seed, int count) {
    Rng rng(seed);
    TearLog log;
    TearSettings ts = w.settings.tear;
    const double area0 = w.cloth.totalRestArea(), uv0 = w.cloth.totalUvArea(), mass0 = w.cloth.totalMass();
    RandomTearRun run;
    for (int i = 0; i < count; ++i) {
        // Prefer springs at tear tips and hinges so weak-point and one-point tears happen often.
        Index s = rng.below(uint32_t(w.cloth.springs.size()));
        if (rng.uniform() < 0.7) {
            for (int tries = 0; tries < 50; ++tries) {
                const Index cand = rng.below(uint32_t(w.cloth.springs.size()));
                const Spring& sp = w.cloth.springs[cand];
                if ((w.cloth.flags[sp.a] | w.cloth.flags[sp.b]) & (kWeak | kHinge)) {
                    s = cand;
                    break;
                }
            }
        }
        // Stretch the spring's neighbourhood a little so the geometric heuristics see a tension.
        TearContext ctx{ts, double(i), &log};
        if (!forceTear(w.cloth, s, ctx)) continue;
        ++run.tears;
        const std::string err = validateCloth(w.cloth, area0, uv0);
        EXPECT_EQ(err, "") << "after tear " << i << " (seed " << seed << ")";
        if (!err.empty()) break;
        EXPECT_NEAR(w.cloth.totalMass(), mass0, 1e-9 * mass0);
    }
    for (int m = 0; m < 3; ++m) run.modes[m] = log.counts[m];
    return run;
}

} // namespace

TEST(TearTopology, RandomForcedTearsKeepEveryInvariantOnAGrid) {
    World w;
    ASSERT_EQ(loadScene(w, "curtain", std::vector<std::string>{"cloth.resolution_x=12", "cloth.resolution_y=12"}), "");
    Rng rng(7);
    const RandomTearRun run = randomTears(w, 1, 400);
    EXPECT_GT(run.tears, 300);
    EXPECT_GT(run.modes[0], 0u);
    EXPECT_GT(run.modes[1], 0u) << "no weak-point tears happened";
    EXPECT_GT(run.modes[2], 0u) << "no one-point separations happened";
    expectUvTiling(w.cloth, rng, 2000);
}

TEST(TearTopology, RandomForcedTearsKeepEveryInvariantOnAnIrregularMesh) {
    for (uint64_t seed = 1; seed <= 5; ++seed) {
        World w;
        ASSERT_EQ(loadScene(w, "irregular", std::vector<std::string>{"cloth.resolution_x=10", "cloth.resolution_y=9",
                                                                     "cloth.seed=" + std::to_string(seed)}),
                  "");
        const RandomTearRun run = randomTears(w, seed * 31, 200);
        EXPECT_GT(run.tears, 100);
        Rng rng(seed);
        expectUvTiling(w.cloth, rng, 500);
    }
}
