// The coarse index buffer of a grid cloth seen from far (render_lod.h, issue 15 goal 5): it covers
// exactly what the fine triangles cover, winds as they do, opens no crack, and leaves torn blocks
// and meshes that are not grids as they are.
#include "render_lod.h"
#include "render_mesh.h"

#include "clothtear/scenes.h"
#include "clothtear/world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

using namespace clothtear;
using namespace clothtear::app;

namespace {

World curtain(int nx, int ny, const std::string& mesh = "grid") {
    World w;
    EXPECT_EQ(loadScene(w, "curtain",
                        std::vector<std::string>{"cloth.resolution_x=" + std::to_string(nx),
                                                 "cloth.resolution_y=" + std::to_string(ny), "cloth.mesh=" + mesh}),
              "");
    return w;
}

// Signed UV area of triangle (a, b, c) of render vertices.
double uvArea(const RenderMesh& m, uint32_t a, uint32_t b, uint32_t c) {
    const double ax = m.uv[2 * a], ay = m.uv[2 * a + 1];
    return 0.5 * ((m.uv[2 * b] - ax) * (m.uv[2 * c + 1] - ay) - (m.uv[2 * c] - ax) * (m.uv[2 * b + 1] - ay));
}

struct Cover {
    double area = 0;        // summed signed UV area
    size_t negative = 0;    // triangles wound against the cloth (clockwise in UV)
};
Cover cover(const RenderMesh& m, const std::vector<uint32_t>& idx) {
    Cover c;
    for (size_t t = 0; t + 2 < idx.size(); t += 3) {
        const double a = uvArea(m, idx[t], idx[t + 1], idx[t + 2]);
        c.area += a;
        c.negative += a < 0;
    }
    return c;
}

// Directed edges of `idx` without their reverse (a crack, or the outline) whose two ends are not
// both on the outline of the fine mesh: where a coarse side skips a point a fine triangle uses.
size_t cracks(const RenderMesh& m, const std::vector<uint32_t>& idx) {
    std::set<std::pair<uint32_t, uint32_t>> edges;
    for (size_t t = 0; t + 2 < idx.size(); t += 3)
        for (int k = 0; k < 3; ++k) edges.insert({idx[t + k], idx[t + (k + 1) % 3]});
    std::set<std::pair<uint32_t, uint32_t>> fineEdges;
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3)
        for (int k = 0; k < 3; ++k) fineEdges.insert({m.indices[t + k], m.indices[t + (k + 1) % 3]});
    std::set<uint32_t> outline; // ends of fine edges without a reverse
    for (const auto& [a, b] : fineEdges)
        if (!fineEdges.count({b, a})) outline.insert(a), outline.insert(b);
    size_t n = 0;
    for (const auto& [a, b] : edges)
        if (!edges.count({b, a}) && !(outline.count(a) && outline.count(b))) ++n;
    return n;
}

} // namespace

// 9 x 9 particles: 8 x 8 cells, 4 x 4 blocks, each two triangles: a quarter of the 128 fine ones.
TEST(AppRenderLod, AnIntactGridDrawsAQuarterOfItsTrianglesOverTheSameArea) {
    World w = curtain(9, 9);
    RenderMesh m;
    m.rebuild(w.cloth);
    const std::vector<uint32_t> coarse = coarseGridIndices(w.cloth, m);
    ASSERT_EQ(m.indices.size(), 128u * 3);
    EXPECT_EQ(coarse.size(), 32u * 3);
    const Cover fine = cover(m, m.indices), c = cover(m, coarse);
    EXPECT_EQ(fine.negative, 0u) << "the cloth winds counter-clockwise in UV";
    EXPECT_EQ(c.negative, 0u);
    EXPECT_NEAR(c.area, fine.area, 1e-9);
    EXPECT_NEAR(c.area, 1.0, 1e-6); // the whole texture square
    EXPECT_EQ(cracks(m, coarse), 0u);
}

// 10 x 10 particles: 9 cells a side, so the last row and column of cells make no full block and
// stay fine, with the midpoints of the blocks beside them.
TEST(AppRenderLod, CellsOutsideFullBlocksStayFineWithoutCracks) {
    World w = curtain(10, 10);
    RenderMesh m;
    m.rebuild(w.cloth);
    const std::vector<uint32_t> coarse = coarseGridIndices(w.cloth, m);
    ASSERT_FALSE(coarse.empty());
    // 16 blocks: the 3 + 3 beside the last column or row are fans of 5 triangles and the one at
    // their corner of 6, the other 9 two triangles; the 17 cells outside blocks keep their 34: 88 of
    // the 162 fine ones.
    EXPECT_EQ(coarse.size() / 3, 6u * 5 + 6u + 9u * 2 + 34u);
    EXPECT_EQ(cover(m, coarse).negative, 0u);
    EXPECT_NEAR(cover(m, coarse).area, cover(m, m.indices).area, 1e-9);
    EXPECT_EQ(cracks(m, coarse), 0u);
}

// A knife cut down the middle: the blocks it crosses keep their triangles (copies of the particles on
// the cut, halved edges), the rest go coarse, and no crack opens between them.
TEST(AppRenderLod, TornBlocksStayFineAndTheirNeighboursCloseOnThem) {
    World w = curtain(33, 33);
    const CutResult cut = w.cut({Vec2d(0.03, 1.5), Vec2d(0.03, -1.5)});
    ASSERT_TRUE(cut.ok()) << cut.error;
    RenderMesh m;
    m.rebuild(w.cloth);
    const std::vector<uint32_t> coarse = coarseGridIndices(w.cloth, m);
    ASSERT_FALSE(coarse.empty());
    const size_t fineTriangles = m.indices.size() / 3, coarseTriangles = coarse.size() / 3;
    EXPECT_LT(coarseTriangles, fineTriangles * 2 / 5);
    EXPECT_GT(coarseTriangles, fineTriangles / 4) << "the cut's blocks are drawn fine";
    EXPECT_EQ(cover(m, coarse).negative, 0u);
    EXPECT_NEAR(cover(m, coarse).area, cover(m, m.indices).area, 1e-9);
    EXPECT_EQ(cracks(m, coarse), 0u);
}

// An irregular mesh has no lattice: nothing to draw coarse.
TEST(AppRenderLod, AMeshThatIsNotAGridHasNoCoarseIndices) {
    World w = curtain(17, 17, "irregular");
    RenderMesh m;
    m.rebuild(w.cloth);
    EXPECT_TRUE(coarseGridIndices(w.cloth, m).empty());
}

// A window 720 pixels tall with a field of view of 2 atan(1/2) sees 1 m across at 1 m: 720 pixels a
// metre, half at twice the distance. A cell of the 2 m curtain at 256 x 256 (mean spring 8.9 mm)
// 3.3 m away (the start camera frames it at 3.9 m) spans 2.3 pixels: drawn coarse; at 128 x 128,
// twice that: drawn fine.
TEST(AppRenderLod, PixelsPerMetreFollowTheFieldOfView) {
    EXPECT_NEAR(pixelsPerMetre(1.f, 2.f * std::atan(0.5f), 720.f), 720.f, 1e-3f);
    EXPECT_NEAR(pixelsPerMetre(2.f, 2.f * std::atan(0.5f), 720.f), 360.f, 1e-3f);
    EXPECT_LT(0.0089f * pixelsPerMetre(3.3f, 0.8f, 720.f), kCoarseBelowPixels);
    EXPECT_GT(2.f * 0.0089f * pixelsPerMetre(3.3f, 0.8f, 720.f), kCoarseBelowPixels);
}
