// Camera math and picking against the cloth, without a window.
#include "camera.h"
#include "picking.h"
#include "render_mesh.h"

#include "clothtear/scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

using namespace clothtear;
using namespace clothtear::app;

TEST(AppCamera, RayThroughCentreIsForwardAndProjectsBack) {
    OrbitCamera cam;
    cam.yaw = 0.7f;
    cam.pitch = -0.3f;
    cam.distance = 7.f;
    const Ray r = rayThroughPixel(cam, 640.f, 360.f, 1280.f, 720.f);
    EXPECT_NEAR((r.dir - cam.forward()).norm(), 0.f, 1e-5f);
    EXPECT_NEAR((r.origin - cam.position()).norm(), 0.f, 1e-5f);
    // Any pixel: a point along its ray projects back onto that pixel.
    const Mat4 vp = cam.viewProjection(1280.f / 720.f);
    for (auto [px, py] : {std::pair{10.f, 20.f}, {1200.f, 700.f}, {333.f, 444.f}}) {
        const Ray ray = rayThroughPixel(cam, px, py, 1280.f, 720.f);
        Vec2 w;
        ASSERT_TRUE(projectToWindow(vp, ray.origin + 3.f * ray.dir, 1280.f, 720.f, w));
        EXPECT_NEAR(w.x(), px, 0.05f);
        EXPECT_NEAR(w.y(), py, 0.05f);
    }
    // Behind the eye does not project.
    Vec2 w;
    EXPECT_FALSE(projectToWindow(vp, cam.position() - cam.forward(), 1280.f, 720.f, w));
}

TEST(AppCamera, ViewMatrixPutsTargetOnTheAxis) {
    OrbitCamera cam;
    cam.target = Vec3(1, 2, 3);
    const Eigen::Vector4f t = cam.view() * Eigen::Vector4f(1, 2, 3, 1);
    EXPECT_NEAR(t.x(), 0.f, 1e-5f);
    EXPECT_NEAR(t.y(), 0.f, 1e-5f);
    EXPECT_NEAR(t.z(), -cam.distance, 1e-4f);
}

TEST(AppCamera, FrameFitsTheBox) {
    OrbitCamera cam;
    cam.frame(Vec3(-1, -1, 0), Vec3(1, 1, 0));
    EXPECT_NEAR(cam.target.norm(), 0.f, 1e-6f);
    const Mat4 vp = cam.viewProjection(16.f / 9.f);
    for (const Vec3& corner : {Vec3(-1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0), Vec3(1, -1, 0)}) {
        Vec2 w;
        ASSERT_TRUE(projectToWindow(vp, corner, 1280.f, 720.f, w));
        EXPECT_GT(w.y(), 0.f);
        EXPECT_LT(w.y(), 720.f);
    }
    const float before = cam.distance;
    cam.zoom(1.f);
    EXPECT_LT(cam.distance, before);
}

// V frames the cloth and its torn pieces: the curtain cut across, its strip (30 % of the area)
// fallen 2.6 m to the ground, is in the picture with the curtain, at 16 and 32 a side.
TEST(AppCamera, FrameWorldShowsATornOffStripOnTheGround) {
    for (int res : {16, 32}) {
        World w;
        const std::string r = std::to_string(res);
        const std::vector<std::string> sets = {"cloth.resolution_x=" + r, "cloth.resolution_y=" + r};
        ASSERT_EQ(loadScene(w, "curtain", sets), "");
        w.step();
        ASSERT_GT(w.cut({Vec2d(-1.2, -0.4), Vec2d(1.2, -0.4)}).particlesAdded, 0u);
        for (int f = 0; f < 180; ++f) w.step();
        OrbitCamera cam;
        frameWorld(cam, w);
        const Mat4 vp = cam.viewProjection(1280.f / 720.f);
        float lowest = 1e30f;
        for (Index p = 0; p < w.cloth.particleCount(); ++p) {
            lowest = std::min(lowest, w.cloth.x[p].y());
            Vec2 px;
            ASSERT_TRUE(projectToWindow(vp, w.cloth.x[p], 1280.f, 720.f, px)) << res << ": particle " << p;
            EXPECT_GE(px.y(), 0.f) << res << ": particle " << p;
            EXPECT_LE(px.y(), 720.f) << res << ": particle " << p;
            EXPECT_GE(px.x(), 0.f) << res << ": particle " << p;
            EXPECT_LE(px.x(), 1280.f) << res << ": particle " << p;
        }
        EXPECT_LT(lowest, -2.8f) << res << ": the strip is on the ground";
    }
}

TEST(AppPicking, RayTriangleHitsInsideAndMissesOutside) {
    const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    Ray r;
    r.origin = Vec3(0.2f, 0.3f, 2.f);
    r.dir = Vec3(0, 0, -1);
    float t, b1, b2;
    ASSERT_TRUE(rayTriangle(r, a, b, c, t, b1, b2));
    EXPECT_NEAR(t, 2.f, 1e-6f);
    EXPECT_NEAR(b1, 0.2f, 1e-6f);
    EXPECT_NEAR(b2, 0.3f, 1e-6f);
    // Two-sided: from behind as well.
    r.origin.z() = -2.f;
    r.dir = Vec3(0, 0, 1);
    EXPECT_TRUE(rayTriangle(r, a, b, c, t, b1, b2));
    r.origin = Vec3(0.8f, 0.8f, 2.f); // outside the hypotenuse
    r.dir = Vec3(0, 0, -1);
    EXPECT_FALSE(rayTriangle(r, a, b, c, t, b1, b2));
    r.origin = Vec3(0.2f, 0.2f, -1.f); // triangle behind the origin
    EXPECT_FALSE(rayTriangle(r, a, b, c, t, b1, b2));
}

TEST(AppPicking, PicksTheClothUnderTheCursorAndItsNearestCorner) {
    World w;
    ASSERT_EQ(loadScene(w, "curtain"), "");
    Ray r;
    r.origin = Vec3(0.013f, 0.021f, 5.f);
    r.dir = Vec3(0, 0, -1);
    const TriangleHit hit = pickTriangle(w.cloth, r);
    ASSERT_TRUE(hit.hit());
    EXPECT_NEAR(hit.point.z(), 0.f, 1e-4f);
    const Index p = nearestCorner(w.cloth, hit);
    ASSERT_NE(p, kNone);
    // No particle of the cloth is nearer to the hit than the chosen corner by more than a spacing.
    const float spacing = w.settings.cloth.width / float(w.settings.cloth.resolutionX - 1);
    EXPECT_LT((w.cloth.x[p] - hit.point).norm(), spacing);
    r.origin = Vec3(50.f, 0.f, 5.f);
    EXPECT_FALSE(pickTriangle(w.cloth, r).hit());
}

TEST(AppPicking, ScreenRadiusSelectsTheParticlesAroundTheCursor) {
    World w;
    ASSERT_EQ(loadScene(w, "curtain"), "");
    OrbitCamera cam;
    cam.target = Vec3::Zero();
    cam.yaw = 0.f;
    cam.pitch = 0.f;
    cam.distance = 4.f;
    const Mat4 vp = cam.viewProjection(1280.f / 720.f);
    const auto all = particlesInScreenRadius(w.cloth, vp, 1280.f, 720.f, Vec2(640, 360), 2000.f);
    EXPECT_EQ(all.size(), w.cloth.particleCount());
    const auto some = particlesInScreenRadius(w.cloth, vp, 1280.f, 720.f, Vec2(640, 360), 40.f);
    EXPECT_GT(some.size(), 0u);
    EXPECT_LT(some.size(), w.cloth.particleCount() / 4);
    for (const auto& s : some) {
        EXPECT_LT(std::abs(w.cloth.x[s.particle].x()), 0.5f);
        EXPECT_GT(s.weight, 0.f);
        EXPECT_LE(s.weight, 1.f);
    }
}

TEST(AppRenderMesh, OneVertexPerParticleAndUvWithIndicesPerTriangle) {
    World w;
    ASSERT_EQ(loadScene(w, "curtain", std::vector<std::string>{"cloth.resolution_x=6", "cloth.resolution_y=5"}), "");
    RenderMesh m;
    EXPECT_TRUE(m.stale(w.cloth));
    m.rebuild(w.cloth);
    EXPECT_FALSE(m.stale(w.cloth));
    EXPECT_EQ(m.vertexCount(), w.cloth.particleCount()); // a grid has one uv per particle
    ASSERT_EQ(m.indices.size(), w.cloth.triangles.size() * 3);
    for (size_t t = 0; t < w.cloth.triangles.size(); ++t)
        for (int c = 0; c < 3; ++c) {
            const uint32_t v = m.indices[t * 3 + c];
            EXPECT_EQ(m.vertexParticle[v], w.cloth.triangles[t].p[c]);
            EXPECT_FLOAT_EQ(m.uv[v * 2], float(w.cloth.triangles[t].uv[c].x()));
            EXPECT_FLOAT_EQ(m.uv[v * 2 + 1], float(w.cloth.triangles[t].uv[c].y()));
        }
    std::vector<Vec3> normals;
    computeParticleNormals(w.cloth, normals);
    for (const Vec3& n : normals) EXPECT_NEAR(std::abs(n.z()), 1.f, 1e-5f); // flat cloth in the x-y plane
    std::vector<float> strain, dyn;
    computeParticleStrain(w.cloth, strain);
    fillDynamicVertices(m, w.cloth, normals, strain, dyn);
    EXPECT_EQ(dyn.size(), m.vertexCount() * kDynamicFloats);
    w.cloth.topologyRevision++;
    EXPECT_TRUE(m.stale(w.cloth));
}

// Torn edges (issue 15, goal 4): a whole cloth has none (its border is all hem); a knife cut down
// the middle of a 10 x 10 curtain (2 m) makes two walls of twin border edges, every one of them torn
// and none of the hem; each fringe strip starts on its edge and reaches out of the cloth, away from
// its triangle's third corner, by 1.4 thread spacings (2 m / 96 threads = 2.08 cm: 2.9 cm).
TEST(AppRenderMesh, TornEdgesAreTheTearsNotTheHemAndTheirFringeReachesOut) {
    World w;
    ASSERT_EQ(loadScene(w, "curtain", std::vector<std::string>{"cloth.resolution_x=10", "cloth.resolution_y=10"}), "");
    EXPECT_TRUE(findTornEdges(w.cloth).empty()) << "a whole cloth: its border is hem";
    size_t borderBefore = 0;
    for (const SpringTopo& t : w.cloth.springTopo) borderBefore += t.tri[1] == kNone;
    const CutResult cut = w.cut({Vec2d(0.05, 1.5), Vec2d(0.05, -1.5)});
    ASSERT_TRUE(cut.ok()) << cut.error;
    ASSERT_GT(cut.springsCut, 0u);
    const std::vector<Index> torn = findTornEdges(w.cloth);
    size_t borderAfter = 0;
    for (const SpringTopo& t : w.cloth.springTopo) borderAfter += t.tri[1] == kNone;
    EXPECT_EQ(torn.size(), 2 * cut.springsCut) << "both walls of every edge cut";
    // The hem is the border that is not torn: the old border plus the springs split where the stroke
    // crosses it (top and bottom, each now two halves: +1 each).
    EXPECT_EQ(borderAfter - torn.size(), borderBefore + 2);
    for (Index s : torn) {
        const Spring& sp = w.cloth.springs[s];
        const float u0 = float(w.cloth.rest[sp.a].x()), u1 = float(w.cloth.rest[sp.b].x());
        EXPECT_NEAR(u0, 0.05f, 0.11f) << "torn edge " << s << " lies along the cut";
        EXPECT_NEAR(u1, 0.05f, 0.11f) << "torn edge " << s << " lies along the cut";
    }
    FringeMesh fringe;
    EXPECT_TRUE(fringe.stale(w.cloth));
    fringe.rebuild(w.cloth, 96.f);
    EXPECT_FALSE(fringe.stale(w.cloth));
    ASSERT_EQ(fringe.edges.size(), torn.size());
    std::vector<Vec3> normals;
    computeParticleNormals(w.cloth, normals);
    std::vector<float> v;
    fillFringeVertices(fringe, w.cloth, normals, v);
    ASSERT_EQ(v.size(), fringe.edges.size() * 4 * kFringeFloats);
    for (size_t e = 0; e < fringe.edges.size(); ++e) {
        const FringeMesh::Edge& edge = fringe.edges[e];
        EXPECT_NEAR(edge.reach, 1.4f * 2.f / 96.f, 1e-3f) << "edge " << e;
        const float* q = &v[e * 4 * kFringeFloats];
        const Vec3 a(q[0], q[1], q[2]), outer(q[3 * kFringeFloats], q[3 * kFringeFloats + 1], q[3 * kFringeFloats + 2]);
        EXPECT_TRUE(a.isApprox(w.cloth.x[edge.a])) << "the strip starts on the edge";
        const Vec3 out = outer - a, in = w.cloth.x[edge.c] - a;
        EXPECT_NEAR(out.norm(), edge.reach, 1e-4f);
        EXPECT_LT(out.dot(in), 0.f) << "edge " << e << ": the threads reach out of the cloth, not over it";
        EXPECT_EQ(q[9], 0.f);
        EXPECT_EQ(q[3 * kFringeFloats + 9], 1.f);
    }
    std::vector<uint32_t> idx;
    fringeIndices(fringe.edges.size(), idx);
    EXPECT_EQ(idx.size(), fringe.edges.size() * 6);
}
