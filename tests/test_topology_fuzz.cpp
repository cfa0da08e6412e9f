// Topology fuzzing: random meshes (grids, irregular, OBJ-like with holes and slivers) torn by random
// sequences of forced tears (random springs, the same place again, cuts right across); validateCloth,
// the rest area, the UV area and the mass hold after every tear, and the torn cloth still simulates.
//
// CI tears at least 10^4 springs; CLOTHTEAR_NIGHTLY=1 tears at least 10^5 (README, "Robustness").
// A failure names the seed: topofuzz::randomMesh and randomTears replay it exactly (streamFor(seed)).
#include "topology_gen.h"

#include "clothtear/world.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>

using namespace clothtear;
using namespace topofuzz;

namespace {

// CLOTHTEAR_TOPOLOGY_TEARS=N asks for N tears; CLOTHTEAR_NIGHTLY=1 for 10^5; else 10^4.
uint64_t tearBudget() {
    if (const char* n = std::getenv("CLOTHTEAR_TOPOLOGY_TEARS"); n && *n)
        return std::strtoull(n, nullptr, 10);
    const char* nightly = std::getenv("CLOTHTEAR_NIGHTLY");
    return nightly && *nightly && std::string(nightly) != "0" ? 100000 : 10000;
}

// Rng(s + k) is Rng(s) k draws later (SplitMix64 steps its state by a constant), so neighbouring
// seeds would share most of their numbers; one SplitMix64 output of the seed starts an unrelated stream.
Rng streamFor(uint64_t seed) {
    return Rng(Rng(seed).next());
}

} // namespace

TEST(TopologyFuzz, RandomTearsOnRandomMeshesKeepEveryInvariant) {
    const uint64_t budget = tearBudget();
    TearStats total;
    std::array<uint64_t, int(MeshKind::Count)> meshes{}, tearsOn{};
    uint64_t seed = 0;
    while (total.torn < budget) {
        ++seed;
        Rng rng = streamFor(seed);
        const MeshKind kind = MeshKind(seed % uint64_t(MeshKind::Count));
        const std::string where = std::string(meshKindName(kind)) + " mesh, seed " + std::to_string(seed);
        const MeshData mesh = randomMesh(kind, rng);
        Result<Cloth> built = buildCloth(mesh, 0.2f);
        ASSERT_TRUE(built.ok()) << where << ": " << built.error;
        Cloth& cloth = built.value;
        const double area = cloth.totalRestArea(), uvArea = cloth.totalUvArea(), mass = cloth.totalMass();
        ASSERT_EQ(validateCloth(cloth, area, uvArea), "") << where;

        std::string failure;
        const int count = 50 + int(rng.below(250));
        const TearStats st = randomTears(cloth, rng, count, [&](uint64_t n) {
            std::string err = validateCloth(cloth, area, uvArea);
            if (err.empty() && std::abs(cloth.totalMass() - mass) > 1e-9 * mass)
                err = "the mass changed";
            if (!err.empty())
                failure = where + ", after tear " + std::to_string(n) + ": " + err;
            return err.empty();
        });
        ASSERT_EQ(failure, "");
        EXPECT_GT(st.torn, 0u) << where;

        // The torn cloth, hung from its top edge, still simulates: finite and valid.
        World world;
        world.settings.check.finite = true;
        ASSERT_EQ(world.rebuild(mesh), "") << where;
        world.cloth = std::move(cloth);
        world.pinByMode(PinMode::TopEdge);
        for (int f = 0; f < 3; ++f)
            world.step();
        EXPECT_TRUE(world.finite) << where << ": " << world.nonFiniteWhere;
        EXPECT_EQ(validateCloth(world.cloth, area, uvArea), "") << where << ", after simulating";

        meshes[int(kind)]++;
        tearsOn[int(kind)] += st.torn;
        total.tried += st.tried;
        total.torn += st.torn;
        total.repeated += st.repeated;
        total.cutLines += st.cutLines;
        total.piecesCut += st.piecesCut;
        for (int m = 0; m < 3; ++m)
            total.modes[m] += st.modes[m];
    }
    std::cout << "topology fuzz: " << total.torn << " tears (" << total.tried << " tried) on " << seed
              << " meshes";
    for (int k = 0; k < int(MeshKind::Count); ++k)
        std::cout << "; " << meshKindName(MeshKind(k)) << ": " << meshes[k] << " meshes, " << tearsOn[k]
                  << " tears";
    std::cout << "\n  basic " << total.modes[0] << ", weak point " << total.modes[1] << ", one point "
              << total.modes[2] << "; repeated at the same place " << total.repeated << "; " << total.cutLines
              << " cuts, " << total.piecesCut << " pieces cut off\n";
    RecordProperty("tears", std::to_string(total.torn));
    // The sequences did what they are for.
    EXPECT_GE(total.torn, budget);
    for (int m = 0; m < 3; ++m)
        EXPECT_GT(total.modes[m], 0u) << "tear mode " << m << " never happened";
    EXPECT_GT(total.repeated, budget / 20);
    EXPECT_GT(total.piecesCut, 0u) << "no cut separated a piece";
}

// The generator's OBJ-like meshes really have holes, slivers and several pieces, or the fuzzing
// above would not be trying them.
TEST(TopologyFuzz, ObjLikeMeshesHaveHolesSliversAndPieces) {
    int withHoles = 0, withSlivers = 0, multiPiece = 0;
    for (uint64_t seed = 1; seed <= 40; ++seed) {
        Rng rng = streamFor(seed);
        std::string text;
        const MeshData mesh = randomMesh(MeshKind::ObjLike, rng, &text);
        ASSERT_FALSE(mesh.triangles.empty()) << "seed " << seed << ":\n" << text;
        Result<Cloth> c = buildCloth(mesh, 0.2f);
        ASSERT_TRUE(c.ok()) << c.error;
        // A full grid of n x m vertices has 2(n-1)(m-1) triangles over its bounding box; holes lose area.
        double minRatio = 1e30;
        for (const Triangle& t : c.value.triangles) {
            const Vec3d &a = c.value.rest[t.p[0]], &b = c.value.rest[t.p[1]], &d = c.value.rest[t.p[2]];
            const double longest = std::max({(b - a).norm(), (d - a).norm(), (d - b).norm()});
            minRatio = std::min(minRatio, t.restArea / (longest * longest));
        }
        withSlivers += minRatio < 1e-3;
        withHoles += text.find("f ") != std::string::npos && pieceCount(c.value) >= 1 &&
                     c.value.totalRestArea() < 0.999 * [&] {
                         Vec3d lo = c.value.rest[0], hi = lo;
                         for (const Vec3d& r : c.value.rest)
                             lo = lo.cwiseMin(r), hi = hi.cwiseMax(r);
                         return (hi.x() - lo.x()) * (hi.y() - lo.y());
                     }();
        multiPiece += pieceCount(c.value) > 1;
    }
    EXPECT_GT(withHoles, 10);
    EXPECT_GT(withSlivers, 5);
    EXPECT_GT(multiPiece, 0);
}
