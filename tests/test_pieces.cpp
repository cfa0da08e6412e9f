// Torn pieces (pieces.h): an untorn cloth is one piece; disjoint parts are pieces with their own
// areas and masses, which add up to the cloth's.
#include "clothtear/pieces.h"
#include "clothtear/tear.h"
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

// Adds `part`, moved by `shift`, to `mesh` as a disjoint part.
void appendPart(MeshData& mesh, const MeshData& part, const Vec3d& shift) {
    const Index base = Index(mesh.positions.size());
    for (const Vec3d& p : part.positions) mesh.positions.push_back(p + shift);
    for (const auto& t : part.triangles) mesh.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    mesh.cornerUVs.insert(mesh.cornerUVs.end(), part.cornerUVs.begin(), part.cornerUVs.end());
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
    auto append = [&](const MeshData& part, const Vec3d& shift) { appendPart(mesh, part, shift); };
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
    // The same areas by label (pieceLabels): every particle's label carries its piece's area.
    const std::vector<Index> label = pieceLabels(c);
    double total = 0;
    const std::vector<double> byLabel = restAreaByLabel(c, label, total);
    EXPECT_NEAR(total, c.totalRestArea(), 1e-9);
    EXPECT_NEAR(byLabel[label[0]], 0.25, 1e-9);   // the 3 x 3 grid, listed first
    EXPECT_NEAR(byLabel[label[9]], 1.0, 1e-9);    // the 5 x 5 grid
    EXPECT_NEAR(byLabel[label[34]], 0.005, 1e-9); // the single triangle
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

// World::deletePiece (issue 14, goal 5): a grid, an irregular mesh and a scrap, disjoint; the middle
// piece taken out whole: the others keep exactly their triangles, rest and UV areas (each part's UVs
// span the unit square) and particles (renumbered), the cloth validates, a driver holding particles
// of two pieces keeps only the other's, and the world steps on.
TEST(Pieces, DeletingAPieceLeavesTheOthersWhole) {
    MeshData mesh;
    auto append = [&](const MeshData& part, const Vec3d& shift) { appendPart(mesh, part, shift); };
    append(makeGridMesh(9, 7, 1.0, 0.8), Vec3d(-2, 0, 0));
    append(makeIrregularMesh(8, 8, 0.7, 0.7, 0.3, 5), Vec3d(0, 0, 0)); // the one deleted
    append(makeGridMesh(2, 2, 0.1, 0.1), Vec3d(2, 0, 0));
    World w;
    w.settings.cloth.pin = PinMode::None;
    w.settings.collision.ground = false;
    ASSERT_EQ(w.rebuild(mesh), "");
    std::vector<Piece> pieces = findPieces(w.cloth);
    ASSERT_EQ(pieces.size(), 3u);
    const Piece big = pieces[0], middle = pieces[1], scrap = pieces[2];
    EXPECT_NEAR(middle.restArea, 0.49, 1e-9);
    EXPECT_EQ(middle.particles, 64u);
    const size_t particles = w.cloth.particleCount(), triangles = w.cloth.triangles.size();
    const double area = w.cloth.totalRestArea(), uv = w.cloth.totalUvArea();
    Driver d;
    d.particles = {w.cloth.triangles[middle.firstTriangle].p[0], w.cloth.triangles[scrap.firstTriangle].p[2]};
    const Vec3d scrapRest = w.cloth.rest[d.particles[1]];
    w.drivers.push_back(d);

    EXPECT_EQ(w.deletePiece(middle.firstTriangle), middle.triangles);
    EXPECT_EQ(validateCloth(w.cloth), "");
    EXPECT_EQ(w.cloth.particleCount(), particles - 64);
    EXPECT_EQ(w.cloth.triangles.size(), triangles - middle.triangles);
    EXPECT_NEAR(w.cloth.totalRestArea(), area - 0.49, 1e-12);
    EXPECT_NEAR(w.cloth.totalUvArea(), uv - 1.0, 1e-12) << "the middle part's whole unit square of texture";
    pieces = findPieces(w.cloth);
    ASSERT_EQ(pieces.size(), 2u);
    EXPECT_EQ(pieces[0].triangles, big.triangles);
    EXPECT_DOUBLE_EQ(pieces[0].restArea, big.restArea);
    EXPECT_EQ(pieces[1].particles, scrap.particles);
    ASSERT_EQ(w.drivers.size(), 1u);
    ASSERT_EQ(w.drivers[0].particles.size(), 1u) << "the deleted piece's particle is let go";
    EXPECT_EQ(w.cloth.rest[w.drivers[0].particles[0]], scrapRest) << "the scrap's, renumbered, is the same particle";
    EXPECT_EQ(w.deletePiece(Index(w.cloth.triangles.size())), 0u) << "no such triangle: nothing happens";
    for (int f = 0; f < 10; ++f) w.step();
    EXPECT_TRUE(w.finite);
    EXPECT_EQ(validateCloth(w.cloth), "");
    // The last piece can go too: an empty cloth steps.
    w.drivers.clear();
    w.deletePiece(0);
    w.deletePiece(0);
    EXPECT_EQ(w.cloth.triangles.size(), 0u);
    EXPECT_EQ(w.cloth.particleCount(), 0u);
    w.step();
    EXPECT_TRUE(w.finite);
}
