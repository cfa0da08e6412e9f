// Texture integrity through tears (Onal 3.3). The grid and irregular meshes take their UVs from the
// rest positions (u = x / width + 1/2, v = y / height + 1/2), an affine map, and tearing must keep
// it: a particle a tear creates sits at a rest point (a midpoint of an edge, or a copy) and must
// carry the UV of that point, the same in every triangle around it (a seam would show otherwise),
// and every triangle keeps UV area / rest area = 1 / (width x height). A split UV placed anywhere
// but the midpoint keeps the total UV area and the tiling (TearTopology) but breaks both of these.
#include "clothtear/cloth.h"
#include "clothtear/mesh.h"
#include "clothtear/random.h"
#include "clothtear/tear.h"

#include <gtest/gtest.h>

#include <string>

using namespace clothtear;

namespace {

constexpr double kWidth = 2.0, kHeight = 1.5;

Vec2d uvOfRest(const Vec3d& r) { return Vec2d(r.x() / kWidth + 0.5, r.y() / kHeight + 0.5); }

// Every corner's UV is the UV of its particle's rest point (so each particle carries one UV in all
// its triangles), and every triangle's UV area over its rest area is 1 / (width x height).
void expectTextureFollowsRest(const Cloth& c, const std::string& where) {
    const double ratio = 1.0 / (kWidth * kHeight);
    for (size_t t = 0; t < c.triangles.size(); ++t) {
        const Triangle& tri = c.triangles[t];
        const double uv = uvArea(tri.uv[0], tri.uv[1], tri.uv[2]);
        ASSERT_NEAR(uv / tri.restArea, ratio, 1e-9 * ratio) << where << ": triangle " << t;
        for (int i = 0; i < 3; ++i)
            ASSERT_LT((tri.uv[i] - uvOfRest(c.rest[tri.p[i]])).norm(), 1e-12)
                << where << ": triangle " << t << " corner " << i << " (particle " << tri.p[i] << ")";
    }
    for (Index p = 0; p < c.particleCount(); ++p) {
        const Triangle& first = c.triangles[c.particleTris[p].front()];
        const Vec2d uv = first.uv[cornerOf(first, p)];
        for (Index t : c.particleTris[p])
            ASSERT_EQ(c.triangles[t].uv[cornerOf(c.triangles[t], p)], uv)
                << where << ": particle " << p << " has two UVs (a seam)";
    }
}

// Forced tears of random springs, most of them at tear tips and hinges so that all three modes
// happen (as TearTopology does), checking the texture after each.
void tearAndCheck(Cloth& c, uint64_t seed, int count, const std::string& mesh) {
    Rng rng(seed);
    TearSettings settings;
    TearLog log;
    for (int i = 0; i < count; ++i) {
        Index s = rng.below(uint32_t(c.springs.size()));
        for (int tries = 0; tries < 50 && rng.uniform() < 0.7; ++tries) {
            const Index cand = rng.below(uint32_t(c.springs.size()));
            if ((c.flags[c.springs[cand].a] | c.flags[c.springs[cand].b]) & (kWeak | kHinge)) {
                s = cand;
                break;
            }
        }
        const TearContext ctx{settings, double(i), &log};
        if (!forceTear(c, s, ctx)) continue;
        expectTextureFollowsRest(c, mesh + " after tear " + std::to_string(i));
        if (::testing::Test::HasFatalFailure()) return;
    }
    for (int m = 0; m < int(TearMode::Knife); ++m) // every mode of the physics (the knife is tests/test_knife.cpp)
        EXPECT_GT(log.counts[m], 0u) << mesh << ": no " << tearModeName(TearMode(m)) << " tear happened";
}

} // namespace

TEST(Texture, EveryTriangleKeepsItsUvToRestAreaRatioAndNoParticleHasASeam) {
    const MeshData grid = makeGridMesh(12, 10, kWidth, kHeight);
    const MeshData irregular = makeIrregularMesh(11, 9, kWidth, kHeight, 0.4, 3);
    for (const auto& [name, mesh] : {std::pair{"grid", &grid}, std::pair{"irregular", &irregular}}) {
        Result<Cloth> built = buildCloth(*mesh, 0.2f);
        ASSERT_TRUE(built.ok()) << built.error;
        expectTextureFollowsRest(built.value, std::string(name) + " untorn");
        tearAndCheck(built.value, 11, 150, name);
    }
}

// One basic tear of an interior spring (a, b): the two new particles (copies of the midpoint, one
// per side) sit at the rest midpoint and carry the midpoint of the edge's UVs in all their triangles.
TEST(Texture, BasicTearGivesTheSplitParticlesTheMidpointUv) {
    Result<Cloth> built = buildCloth(makeGridMesh(6, 6, kWidth, kHeight), 0.2f);
    ASSERT_TRUE(built.ok()) << built.error;
    Cloth& c = built.value;
    Index s = 0;
    while (c.springTopo[s].tri[1] == kNone) ++s; // the first interior spring
    const Index a = c.springs[s].a, b = c.springs[s].b;
    const Triangle& t0 = c.triangles[c.springTopo[s].tri[0]];
    const Vec2d mid = 0.5 * (t0.uv[cornerOf(t0, a)] + t0.uv[cornerOf(t0, b)]);
    const size_t before = c.particleCount();
    TearSettings settings;
    TearLog log;
    ASSERT_TRUE(forceTear(c, s, TearContext{settings, 0.0, &log}));
    ASSERT_EQ(log.counts[int(TearMode::Basic)], 1u);
    ASSERT_EQ(c.particleCount(), before + 2);
    for (Index p = Index(before); p < c.particleCount(); ++p) {
        EXPECT_EQ(c.rest[p], 0.5 * (c.rest[a] + c.rest[b]));
        ASSERT_EQ(c.particleTris[p].size(), 2u) << "each copy belongs to one half of each split triangle";
        for (Index t : c.particleTris[p])
            EXPECT_LT((c.triangles[t].uv[cornerOf(c.triangles[t], p)] - mid).norm(), 1e-15) << "particle " << p;
    }
    expectTextureFollowsRest(c, "after one basic tear");
}
