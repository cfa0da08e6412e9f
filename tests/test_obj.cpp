// OBJ import/export: exact round trip, polygon triangulation, face forms and planar UVs, and one
// "file:line: what" message per bad input.
#include "clothtear/cloth.h"
#include "clothtear/mesh.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

using namespace clothtear;
namespace fs = std::filesystem;

namespace {

// Each test writes its files into its own fresh directory under the system temp dir.
class ObjTempDir : public ::testing::Test {
  protected:
    void SetUp() override {
        const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() / ("clothtear_obj_" + std::string(info->test_suite_name()) + "_" +
                                            info->name() + "_" + std::to_string(std::random_device{}()));
        fs::remove_all(dir_);
        ASSERT_TRUE(fs::create_directories(dir_)) << dir_;
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    std::string write(const std::string& name, const std::string& text) const {
        std::ofstream out(path(name), std::ios::binary);
        out << text;
        EXPECT_TRUE(out.good()) << name;
        return path(name);
    }
    Result<MeshData> load(const std::string& name, const std::string& text) const {
        const std::string file = write(name, text);
        Result<MeshData> r;
        EXPECT_NO_THROW(r = loadObj(file));
        return r;
    }

    fs::path dir_;
};

class ObjRoundTrip : public ObjTempDir {};
class ObjImport : public ObjTempDir {};
class ObjErrors : public ObjTempDir {};
class ObjExport : public ObjTempDir {};

// A failed load whose single-line message contains `where` (e.g. "bad.obj:5:") and `what`.
::testing::AssertionResult failsWith(const Result<MeshData>& r, const std::string& where,
                                     const std::string& what) {
    if (r.ok())
        return ::testing::AssertionFailure() << "loaded without an error";
    if (r.error.find(where) == std::string::npos || r.error.find(what) == std::string::npos)
        return ::testing::AssertionFailure()
               << "message \"" << r.error << "\" lacks \"" << where << "\" or \"" << what << "\"";
    if (r.error.find('\n') != std::string::npos)
        return ::testing::AssertionFailure() << "message is not one line: \"" << r.error << "\"";
    return ::testing::AssertionSuccess();
}

double meshArea(const MeshData& m) {
    double a = 0;
    for (const auto& t : m.triangles)
        a += triangleArea(m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]);
    return a;
}

size_t countLinesStartingWith(const std::string& file, const std::string& prefix) {
    std::ifstream in(file);
    size_t n = 0;
    for (std::string line; std::getline(in, line);)
        if (line.rfind(prefix, 0) == 0)
            ++n;
    return n;
}

// Three vertices of a unit right triangle, lines 1-3; a test appends its own lines from line 4.
const std::string kTriangleVertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

} // namespace

// ---- round trip -----------------------------------------------------------------------------------

TEST_F(ObjRoundTrip, IrregularMeshSurvivesSaveAndLoadExactly) {
    const double width = 1.6, height = 1.1;
    const MeshData original = makeIrregularMesh(12, 9, width, height, 0.3, 7);
    const std::string file = path("irregular.obj");
    ASSERT_TRUE(saveObj(original, file));
    EXPECT_EQ(countLinesStartingWith(file, "v "), original.positions.size());
    EXPECT_EQ(countLinesStartingWith(file, "vt "), 3 * original.triangles.size()); // one per corner
    EXPECT_EQ(countLinesStartingWith(file, "f "), original.triangles.size());

    const Result<MeshData> loaded = loadObj(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error;
    const MeshData& m = loaded.value;
    ASSERT_EQ(m.positions.size(), original.positions.size());
    ASSERT_EQ(m.triangles.size(), original.triangles.size());
    ASSERT_EQ(m.cornerUVs.size(), original.cornerUVs.size());
    for (size_t v = 0; v < m.positions.size(); ++v)
        for (int i = 0; i < 3; ++i)
            ASSERT_NEAR(m.positions[v][i], original.positions[v][i], 1e-12) << "vertex " << v;
    for (size_t t = 0; t < m.triangles.size(); ++t) {
        ASSERT_EQ(m.triangles[t], original.triangles[t]) << "triangle " << t;
        for (int k = 0; k < 3; ++k) {
            ASSERT_NEAR(m.cornerUVs[t][k].x(), original.cornerUVs[t][k].x(), 1e-12) << "triangle " << t;
            ASSERT_NEAR(m.cornerUVs[t][k].y(), original.cornerUVs[t][k].y(), 1e-12) << "triangle " << t;
        }
    }

    const Result<Cloth> a = buildCloth(original, 0.2f);
    const Result<Cloth> b = buildCloth(m, 0.2f);
    ASSERT_TRUE(a.ok()) << a.error;
    ASSERT_TRUE(b.ok()) << b.error;
    EXPECT_NEAR(b.value.totalRestArea(), a.value.totalRestArea(), 1e-12);
    EXPECT_NEAR(b.value.totalRestArea(), width * height, 1e-9); // the outline stays a rectangle
    EXPECT_EQ(b.value.particleCount(), a.value.particleCount());
    EXPECT_EQ(b.value.particleCount(), size_t(12 * 9));
    EXPECT_EQ(b.value.springs.size(), a.value.springs.size());
    EXPECT_EQ(b.value.bends.size(), a.value.bends.size());
    EXPECT_EQ(b.value.triangles.size(), a.value.triangles.size());
}

// ---- import ---------------------------------------------------------------------------------------

TEST_F(ObjImport, QuadsAreFanTriangulated) {
    const Result<MeshData> r = load("quads.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\n"
                                                 "f 1 2 5 4\nf 2 3 6 5\n");
    ASSERT_TRUE(r.ok()) << r.error;
    const MeshData& m = r.value;
    ASSERT_EQ(m.triangles.size(), 4u);
    EXPECT_EQ(m.triangles[0], (std::array<Index, 3>{0, 1, 4}));
    EXPECT_EQ(m.triangles[1], (std::array<Index, 3>{0, 4, 3}));
    EXPECT_EQ(m.triangles[2], (std::array<Index, 3>{1, 2, 5}));
    EXPECT_EQ(m.triangles[3], (std::array<Index, 3>{1, 5, 4}));
    EXPECT_NEAR(meshArea(m), 2.0, 1e-12);

    const Result<Cloth> c = buildCloth(m, 0.2f);
    ASSERT_TRUE(c.ok()) << c.error;
    EXPECT_NEAR(c.value.totalRestArea(), 2.0, 1e-12);
    EXPECT_EQ(c.value.particleCount(), 6u);
    EXPECT_EQ(c.value.springs.size(), 9u); // V - E + F = 1 for a disc
    EXPECT_EQ(c.value.bends.size(), 3u);   // interior edges: 9 - 6 on the border
}

TEST_F(ObjImport, PentagonIsFanTriangulatedWithItsAreaAndPlanarUVs) {
    // Convex pentagon (0,0) (2,0) (3,1.5) (1,3) (-1,1.5), shoelace area 7.5, placed in a tilted plane:
    // (x, s) -> (x, 0.6 s, 0.8 s) keeps lengths, hence the area.
    std::ostringstream text;
    const double xs[5] = {0, 2, 3, 1, -1}, ss[5] = {0, 0, 1.5, 3, 1.5};
    for (int i = 0; i < 5; ++i)
        text << "v " << xs[i] << " " << 0.6 * ss[i] << " " << 0.8 * ss[i] << "\n";
    text << "f 1 2 3 4 5\n";
    const Result<MeshData> r = load("pentagon.obj", text.str());
    ASSERT_TRUE(r.ok()) << r.error;
    const MeshData& m = r.value;
    ASSERT_EQ(m.triangles.size(), 3u);
    EXPECT_EQ(m.triangles[0], (std::array<Index, 3>{0, 1, 2}));
    EXPECT_EQ(m.triangles[1], (std::array<Index, 3>{0, 2, 3}));
    EXPECT_EQ(m.triangles[2], (std::array<Index, 3>{0, 3, 4}));
    EXPECT_NEAR(meshArea(m), 7.5, 1e-12);
    // Extents: x 4, y 1.8, z 2.4: the planar projection keeps x and z, normalized to the box.
    for (size_t t = 0; t < 3; ++t)
        for (int k = 0; k < 3; ++k) {
            const Vec3d& p = m.positions[m.triangles[t][k]];
            EXPECT_NEAR(m.cornerUVs[t][k].x(), (p.x() + 1.0) / 4.0, 1e-12);
            EXPECT_NEAR(m.cornerUVs[t][k].y(), p.z() / 2.4, 1e-12);
        }
    const Result<Cloth> c = buildCloth(m, 0.2f);
    ASSERT_TRUE(c.ok()) << c.error;
    EXPECT_NEAR(c.value.totalRestArea(), 7.5, 1e-12);
    EXPECT_EQ(c.value.particleCount(), 5u);
}

TEST_F(ObjImport, EveryFaceFormNegativeIndicesCommentsAndCrlf) {
    const std::string lines[] = {
        "# every corner form", // 1
        "o cloth",             // 2
        "v 0 0 0",             // 3  v1
        "v 1 0 0",             // 4  v2
        "v\t1 1 0   # tabs",   // 5  v3
        "v 0 1 0",             // 6  v4
        "v 2 0 0",             // 7  v5
        "v 2 1 0",             // 8  v6
        "vt 0.1 0.2",          // 9  t1
        "vt 0.9 0.2",          // 10 t2
        "vt 0.9 0.8",          // 11 t3
        "vt 0.1 0.8",          // 12 t4
        "vn 0 0 1",            // 13 n1
        "g part",              // 14
        "usemtl cotton",       // 15
        "s off",               // 16
        "f 1 2 3 # plain",     // 17 -> {0,1,2}, planar UVs
        "f 1/1 3/3 4/4",       // 18 -> {0,2,3}, t1 t3 t4
        "f 2/2/1 5/1/1 6/3/1", // 19 -> {1,4,5}, t2 t1 t3
        "f 2//1 6//1 3//1",    // 20 -> {1,5,2}, planar UVs
        "v 3 0 0",             // 21 v7
        "v 3 1 0",             // 22 v8
        "f -4/-3 -2/-2 -1/-1", // 23 -> {4,6,7}, t2 t3 t4
    };
    std::string text;
    for (const std::string& l : lines)
        text += l + "\r\n";
    const Result<MeshData> r = load("forms.obj", text);
    ASSERT_TRUE(r.ok()) << r.error;
    const MeshData& m = r.value;
    ASSERT_EQ(m.positions.size(), 8u);
    ASSERT_EQ(m.triangles.size(), 5u);
    const std::array<Index, 3> tris[5] = {{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}, {4, 6, 7}};
    for (size_t t = 0; t < 5; ++t)
        EXPECT_EQ(m.triangles[t], tris[t]) << "triangle " << t;
    const Vec2d t1(0.1, 0.2), t2(0.9, 0.2), t3(0.9, 0.8), t4(0.1, 0.8);
    const Vec2d given[3][3] = {{t1, t3, t4}, {t2, t1, t3}, {t2, t3, t4}};
    const size_t withUV[3] = {1, 2, 4};
    for (int f = 0; f < 3; ++f)
        for (int k = 0; k < 3; ++k)
            EXPECT_TRUE(m.cornerUVs[withUV[f]][k].isApprox(given[f][k], 1e-15)) << "triangle " << withUV[f];
    // Planar UVs over the box x 0..3, y 0..1 (z has no extent): u = x / 3, v = y.
    for (size_t t : {size_t(0), size_t(3)})
        for (int k = 0; k < 3; ++k) {
            const Vec3d& p = m.positions[m.triangles[t][k]];
            EXPECT_NEAR(m.cornerUVs[t][k].x(), p.x() / 3.0, 1e-15) << "triangle " << t;
            EXPECT_NEAR(m.cornerUVs[t][k].y(), p.y(), 1e-15) << "triangle " << t;
        }
    EXPECT_TRUE(buildCloth(m, 0.2f).ok());
}

TEST_F(ObjImport, FacesMayReferToVerticesDefinedLater) {
    const Result<MeshData> r = load("forward.obj", "f 1 2 3\n" + kTriangleVertices);
    ASSERT_TRUE(r.ok()) << r.error;
    ASSERT_EQ(r.value.triangles.size(), 1u);
    EXPECT_NEAR(meshArea(r.value), 0.5, 1e-15);
}

TEST_F(ObjImport, NonManifoldEdgeLoadsButBuildClothRefusesIt) {
    // Three triangles share the edge 1-2.
    const Result<MeshData> r =
        load("fin.obj", kTriangleVertices + "v 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n");
    ASSERT_TRUE(r.ok()) << r.error;
    ASSERT_EQ(r.value.triangles.size(), 3u);
    const Result<Cloth> c = buildCloth(r.value, 0.2f);
    ASSERT_FALSE(c.ok());
    EXPECT_NE(c.error.find("non-manifold"), std::string::npos) << c.error;
    EXPECT_NE(c.error.find("between vertices 1 and 2"), std::string::npos) << c.error;
}

// The message names the shared edge even when the third face was flipped to be counter-clockwise in
// UV space (the corners are re-ordered; the message once took the edge from the unflipped order and
// named 2-4 here).
TEST_F(ObjImport, NonManifoldMessageNamesTheEdgeOfAFlippedFace) {
    const Result<MeshData> r = load("fin2.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 2 1 4\n");
    ASSERT_TRUE(r.ok()) << r.error;
    const Result<Cloth> c = buildCloth(r.value, 0.2f);
    ASSERT_FALSE(c.ok());
    const bool named = c.error.find("between vertices 1 and 2 ") != std::string::npos ||
                       c.error.find("between vertices 2 and 1 ") != std::string::npos;
    EXPECT_TRUE(named) << c.error;
}

// ---- bad inputs: one clear line naming the file (and the line where there is one) -------------------

TEST_F(ObjErrors, MissingFile) {
    Result<MeshData> r;
    EXPECT_NO_THROW(r = loadObj(path("missing.obj")));
    EXPECT_TRUE(failsWith(r, "missing.obj", "cannot open"));
}

TEST_F(ObjErrors, DirectoryInsteadOfFile) {
    ASSERT_TRUE(fs::create_directory(path("folder.obj")));
    Result<MeshData> r;
    EXPECT_NO_THROW(r = loadObj(path("folder.obj")));
    EXPECT_TRUE(failsWith(r, "folder.obj", "is a directory"));
}

TEST_F(ObjErrors, EmptyFileHasNoFaces) {
    EXPECT_TRUE(failsWith(load("empty.obj", ""), "empty.obj", "no faces"));
    EXPECT_TRUE(
        failsWith(load("points.obj", "# only vertices\n" + kTriangleVertices), "points.obj", "no faces"));
}

TEST_F(ObjErrors, BinaryGarbage) {
    // An ELF header after one good line: the first control byte (0x7f) is on line 2.
    std::string bytes = "v 0 0 0\n\x7f"
                        "ELF\x02\x01\x01";
    bytes += std::string(1, '\0');
    for (int i = 0; i < 256; ++i)
        bytes += static_cast<char>((i * 73 + 11) & 0xff);
    EXPECT_TRUE(
        failsWith(load("garbage.obj", bytes), "garbage.obj:2:", "binary data (byte 0x7f at column 1)"));
    EXPECT_TRUE(failsWith(load("zeros.obj", std::string(64, '\0')), "zeros.obj:1:", "binary data"));
}

TEST_F(ObjErrors, FaceVertexIndexOutOfRange) {
    EXPECT_TRUE(failsWith(load("range.obj", kTriangleVertices + "f 1 2 3\nf 1 2 40\n"),
                          "range.obj:5:", "face refers to vertex 40 but only 3 vertices are defined"));
    EXPECT_TRUE(failsWith(load("relative.obj", kTriangleVertices + "f -1 -2 -5\n"), "relative.obj:4:",
                          "face refers to vertex -5 but only 3 vertices are defined before this line"));
    EXPECT_TRUE(
        failsWith(load("zero.obj", kTriangleVertices + "f 0 1 2\n"), "zero.obj:4:", "index 0 is invalid"));
}

TEST_F(ObjErrors, FaceWithFewerThanThreeVertices) {
    EXPECT_TRUE(failsWith(load("two.obj", kTriangleVertices + "f 1 2\n"),
                          "two.obj:4:", "face has 2 vertices; a face needs at least 3"));
}

TEST_F(ObjErrors, NonNumericCoordinate) {
    EXPECT_TRUE(failsWith(load("word.obj", "v 0 0 0\nv 1 abc 0\nv 0 1 0\nf 1 2 3\n"),
                          "word.obj:2:", "vertex 2: 'abc' is not a number"));
    EXPECT_TRUE(failsWith(load("short.obj", "v 0 0 0\nv 1 0\n"), "short.obj:2:", "vertex 2 has 2 numbers"));
    EXPECT_TRUE(failsWith(load("uvword.obj", kTriangleVertices + "vt 0 x\n"),
                          "uvword.obj:4:", "texture coordinate 1: 'x' is not a number"));
}

TEST_F(ObjErrors, NanAndInfiniteCoordinates) {
    EXPECT_TRUE(failsWith(load("nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n"),
                          "nan.obj:3:", "vertex 3 has a non-finite coordinate 'nan'"));
    EXPECT_TRUE(failsWith(load("inf.obj", "v 0 0 0\nv 1 -inf 0\n"),
                          "inf.obj:2:", "vertex 2 has a non-finite coordinate '-inf'"));
    EXPECT_TRUE(failsWith(load("huge.obj", "v 1e999 0 0\n"), "huge.obj:1:", "out of the range of a double"));
}

TEST_F(ObjErrors, DegenerateFaces) {
    EXPECT_TRUE(failsWith(load("line.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n"),
                          "line.obj:4:", "face is degenerate (zero area)"));
    EXPECT_TRUE(failsWith(load("repeat.obj", kTriangleVertices + "f 1 2 2\n"),
                          "repeat.obj:4:", "face uses vertex 2 more than once"));
    // A quad whose first three corners are collinear: the first fan triangle has no area.
    EXPECT_TRUE(failsWith(load("fan.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 1 1 0\nf 1 2 3 4\n"),
                          "fan.obj:5:", "fan triangle 1 of 2 has zero area"));
}

TEST_F(ObjErrors, TextureIndexOutOfRange) {
    EXPECT_TRUE(failsWith(load("vt.obj", kTriangleVertices + "vt 0 0\nvt 1 0\nf 1/1 2/2 3/9\n"), "vt.obj:6:",
                          "face refers to texture coordinate 9 but only 2 texture coordinates are defined"));
    EXPECT_TRUE(failsWith(load("vtrel.obj", kTriangleVertices + "vt 0 0\nf 1/-1 2/-1 3/-2\n"), "vtrel.obj:5:",
                          "face refers to texture coordinate -2 but only 1 texture coordinate is defined"));
}

TEST_F(ObjErrors, MalformedOrMixedFaceCorners) {
    EXPECT_TRUE(failsWith(load("slash.obj", kTriangleVertices + "f 1/ 2 3\n"),
                          "slash.obj:4:", "malformed face corner '1/'"));
    EXPECT_TRUE(failsWith(load("four.obj", kTriangleVertices + "f 1/1/1/1 2 3\n"),
                          "four.obj:4:", "malformed face corner '1/1/1/1'"));
    EXPECT_TRUE(failsWith(load("letter.obj", kTriangleVertices + "f 1 b 3\n"),
                          "letter.obj:4:", "'b' is not an integer index"));
    EXPECT_TRUE(failsWith(load("mixed.obj", kTriangleVertices + "vt 0 0\nf 1/1 2 3\n"),
                          "mixed.obj:5:", "face mixes corners with and without texture coordinates"));
}

// ---- export -----------------------------------------------------------------------------------------

TEST_F(ObjExport, ReturnsFalseWhenTheFileCannotBeWritten) {
    const MeshData mesh = makeGridMesh(3, 3, 1.0, 1.0);
    EXPECT_FALSE(saveObj(mesh, path("no_such_dir/cloth.obj")));
    EXPECT_FALSE(saveObj(mesh, dir_.string())); // a directory
    EXPECT_FALSE(fs::exists(path("no_such_dir")));
    MeshData broken = mesh;
    broken.cornerUVs.pop_back(); // one UV triple short: not a mesh that can be written
    EXPECT_FALSE(saveObj(broken, path("broken.obj")));
    EXPECT_TRUE(saveObj(mesh, path("ok.obj")));
}
