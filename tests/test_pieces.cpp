// Torn pieces (pieces.h): an untorn cloth is one piece; disjoint parts are pieces with their own
// areas and masses, which add up to the cloth's.
#include "clothtear/pieces.h"
#include "clothtear/scenes.h"
#include "clothtear/mesh.h"
#include "clothtear/world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

using namespace clothtear;

namespace {

World loadOrFail(const std::string& scene, const std::vector<std::string>& sets) {
    World w;
    EXPECT_EQ(loadScene(w, scene, sets), "");
    return w;
}

} // namespace

TEST(Pieces, AnUntornClothIsOnePieceWithAllItsAreaAndMass) {
    for (const char* mesh : {"grid", "irregular"}) {
        World w = loadOrFail("curtain", {"cloth.resolution_x=12", "cloth.resolution_y=9", std::string("cloth.mesh=") + mesh});
        const std::vector<Piece> pieces = findPieces(w.cloth);
        ASSERT_EQ(pieces.size(), 1u) << mesh;
        EXPECT_EQ(pieces[0].triangles, w.cloth.triangles.size()) << mesh;
        EXPECT_EQ(pieces[0].particles, w.cloth.particleCount()) << mesh;
        EXPECT_NEAR(pieces[0].restArea, w.cloth.totalRestArea(), 1e-9) << mesh;
        EXPECT_NEAR(pieces[0].mass, w.cloth.totalMass(), 1e-6) << mesh;
    }
}

// A mesh of three disjoint parts: a 1 m square, a 0.5 m square and one triangle of 50 cm^2 (a
// scrap). Three pieces, largest first, with their rest areas, triangle and particle counts and
// masses (density x area); they add up to the cloth's.
TEST(Pieces, ThreeDisjointPartsAreThreePiecesLargestFirst) {
    MeshData mesh;
    auto append = [&](const MeshData& part, const Vec3d& shift) {
        const Index base = Index(mesh.positions.size());
        for (const Vec3d& p : part.positions) mesh.positions.push_back(p + shift);
        for (const auto& t : part.triangles) mesh.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
        mesh.cornerUVs.insert(mesh.cornerUVs.end(), part.cornerUVs.begin(), part.cornerUVs.end());
    };
    append(makeGridMesh(3, 3, 0.5, 0.5), Vec3d(2, 0, 0)); // listed first: the order is by area, not input
    append(makeGridMesh(5, 5, 1.0, 1.0), Vec3d(-2, 0, 0));
    MeshData scrap;
    scrap.positions = {Vec3d(5, 0, 0), Vec3d(5.1, 0, 0), Vec3d(5, 0.1, 0)};
    scrap.triangles = {{0, 1, 2}};
    scrap.cornerUVs = {{Vec2d(0, 0), Vec2d(1, 0), Vec2d(0, 1)}};
    append(scrap, Vec3d::Zero());
    Result<Cloth> built = buildCloth(mesh, 0.2f);
    ASSERT_TRUE(built.ok()) << built.error;
    const Cloth& c = built.value;
    const std::vector<Piece> pieces = findPieces(c);
    ASSERT_EQ(pieces.size(), 3u);
    const double areas[3] = {1.0, 0.25, 0.005};
    const size_t triangles[3] = {32, 8, 1}, particles[3] = {25, 9, 3};
    double areaSum = 0, massSum = 0;
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(pieces[k].restArea, areas[k], 1e-9) << k;
        EXPECT_EQ(pieces[k].triangles, triangles[k]) << k;
        EXPECT_EQ(pieces[k].particles, particles[k]) << k;
        EXPECT_NEAR(pieces[k].mass, 0.2 * areas[k], 1e-7) << k;
        areaSum += pieces[k].restArea, massSum += pieces[k].mass;
    }
    EXPECT_NEAR(areaSum, c.totalRestArea(), 1e-9);
    EXPECT_NEAR(massSum, c.totalMass(), 1e-6);
}

// The torn cloth exported (clothMesh + saveObj, what --export-obj and the panel write) and read back
// builds the same cloth: the same triangles and pieces, every particle where it was, and the texture
// whole (UV area and rest area as before the tear).
TEST(Pieces, ATornClothExportsAndLoadsBackWithItsPiecesAndTexture) {
    World w = loadOrFail("ball-r0.5-v3", {"cloth.resolution_x=24", "cloth.resolution_y=24"});
    const double uvArea0 = w.cloth.totalUvArea(), restArea0 = w.cloth.totalRestArea();
    for (int f = 0; f < 90; ++f) w.step();
    ASSERT_GT(w.tearLog.total(), 0u) << "the ball tears the cloth";
    const std::vector<Piece> before = findPieces(w.cloth);
    const std::string path = (std::filesystem::temp_directory_path() / "clothtear_export_torn.obj").string();
    for (bool restShape : {false, true}) {
        ASSERT_TRUE(saveObj(clothMesh(w.cloth, restShape), path));
        Result<MeshData> loaded = loadObj(path);
        ASSERT_TRUE(loaded.ok()) << loaded.error;
        Result<Cloth> back = buildCloth(loaded.value, w.cloth.density);
        ASSERT_TRUE(back.ok()) << back.error;
        EXPECT_EQ(back.value.triangles.size(), w.cloth.triangles.size());
        EXPECT_EQ(back.value.particleCount(), w.cloth.particleCount());
        const std::vector<Piece> after = findPieces(back.value);
        ASSERT_EQ(after.size(), before.size()) << (restShape ? "rest shape" : "current shape");
        for (size_t i = 0; i < after.size(); ++i) EXPECT_EQ(after[i].triangles, before[i].triangles);
        EXPECT_NEAR(back.value.totalUvArea(), uvArea0, 1e-9);
        if (restShape) {
            EXPECT_NEAR(back.value.totalRestArea(), restArea0, 1e-9);
        }
        // The particles as sets (the import may number them in another order).
        auto sorted = [](std::vector<Vec3d> v) {
            std::sort(v.begin(), v.end(), [](const Vec3d& a, const Vec3d& b) {
                return a.x() != b.x() ? a.x() < b.x() : a.y() != b.y() ? a.y() < b.y() : a.z() < b.z();
            });
            return v;
        };
        std::vector<Vec3d> want;
        for (Index p = 0; p < w.cloth.particleCount(); ++p)
            want.push_back(restShape ? w.cloth.rest[p] : Vec3d(w.cloth.x[p].cast<double>()));
        const std::vector<Vec3d> a = sorted(want), b = sorted(back.value.rest);
        double worst = 0;
        for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, (a[i] - b[i]).norm());
        EXPECT_LT(worst, 1e-9) << "every particle where it was (OBJ keeps doubles)";
    }
}
