// What the OBJ importer and buildCloth refuse beyond syntax (mesh.h limits), and the planar UVs of
// faces edge-on to the projection: each found by fuzzing (fuzz/regressions/obj).
#include "clothtear/cloth.h"
#include "clothtear/mesh.h"
#include "clothtear/tear.h"

#include <gtest/gtest.h>

using namespace clothtear;

namespace {

const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

::testing::AssertionResult refused(const std::string& text, const std::string& expected) {
    const Result<MeshData> r = parseObj(text, "m.obj");
    if (r.ok())
        return ::testing::AssertionFailure() << "accepted:\n" << text;
    if (r.error.find(expected) == std::string::npos)
        return ::testing::AssertionFailure() << "'" << r.error << "' lacks '" << expected << "'";
    return ::testing::AssertionSuccess();
}

} // namespace

TEST(ObjLimits, CoordinatesTheFloatStateCannotHoldAreRefusedWithTheirLine) {
    EXPECT_TRUE(refused("v 0 0 0\nv 1e39 0 0\n", "m.obj:2: vertex 2: '1e39' is beyond +-1e5 m"));
    EXPECT_TRUE(
        refused(kTriangle + "vt 0 0\nvt 1e7 0\n", "m.obj:5: texture coordinate 2: '1e7' is beyond +-1e6"));
    EXPECT_TRUE(parseObj("v 0 0 0\nv 1e5 0 0\nv 0 1e5 0\nf 1 2 3\n", "m.obj").ok())
        << "the limit itself is allowed";
}

TEST(ObjLimits, EdgesTooShortForAFloatRestLengthAreRefused) {
    EXPECT_TRUE(refused("v 0 0 0\nv 1 0 0\nv 0 1e-8 1\nv 0 0 1e-8\nf 1 2 4\n",
                        "m.obj:5: face has an edge of 1e-08 m"));
}

TEST(ObjLimits, TextureTrianglesWithoutAreaAreRefused) {
    EXPECT_TRUE(refused(kTriangle + "vt 0.5 0.5\nf 1/1 2/1 3/1\n",
                        "m.obj:5: face has texture coordinates with zero area"));
    EXPECT_TRUE(refused(kTriangle + "vt 0 0\nvt 1 1\nvt 2 2\nf 1/1 2/2 3/3\n",
                        "m.obj:7: face has texture coordinates"));
}

// No vt: the mesh's planar projection (x-y here) would flatten the face in the x = 0 plane to a line;
// it gets a projection of its own and the cloth builds valid, and stays valid when torn.
TEST(ObjLimits, FaceEdgeOnToThePlanarProjectionGetsItsOwn) {
    const Result<MeshData> r =
        parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 3\nv 1 1 0\nf 1 2 3\nf 1 3 4\nf 2 5 3\n", "fold.obj");
    ASSERT_TRUE(r.ok()) << r.error;
    for (const auto& uv : r.value.cornerUVs)
        EXPECT_GT(std::abs(uvArea(uv[0], uv[1], uv[2])), 1e-3);
    Result<Cloth> c = buildCloth(r.value, 0.2f);
    ASSERT_TRUE(c.ok()) << c.error;
    const double area = c.value.totalRestArea(), uv = c.value.totalUvArea();
    EXPECT_EQ(validateCloth(c.value, area, uv), "");
    TearSettings ts;
    const TearContext ctx{ts, 0.0, nullptr};
    for (Index s = 0; s < 4; ++s) {
        forceTear(c.value, s, ctx);
        EXPECT_EQ(validateCloth(c.value, area, uv), "") << "after tearing spring " << s;
    }
}

TEST(ObjLimits, DoubledFaceIsRefusedByBuildCloth) {
    const Result<MeshData> r = parseObj(kTriangle + "f 1 2 3\nf 3 1 2\n", "twice.obj");
    ASSERT_TRUE(r.ok()) << r.error;
    const Result<Cloth> c = buildCloth(r.value, 0.2f);
    ASSERT_FALSE(c.ok());
    EXPECT_EQ(c.error, "mesh: faces 1 and 2 use the same three vertices (a doubled face)");
}

TEST(ObjLimits, CheckMeshHoldsEveryMeshSourceToTheSameLimits) {
    MeshData m = makeGridMesh(3, 3, 1.0, 1.0);
    EXPECT_EQ(checkMesh(m, "grid"), "");
    MeshData far = m;
    far.positions[4].x() = 2e5;
    EXPECT_NE(checkMesh(far, "grid").find("vertex 5 lies beyond +-100000 m"), std::string::npos)
        << checkMesh(far, "grid");
    MeshData flatUv = m;
    flatUv.cornerUVs[2] = {Vec2d(0, 0), Vec2d(0, 0), Vec2d(1, 0)};
    EXPECT_NE(checkMesh(flatUv, "grid").find("face 3 has texture coordinates with zero area"),
              std::string::npos);
    MeshData tiny = makeGridMesh(3, 3, 1e-7, 1e-7);
    EXPECT_NE(checkMesh(tiny, "grid").find("edges under 1e-7 m"), std::string::npos)
        << checkMesh(tiny, "grid");
}
