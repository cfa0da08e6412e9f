// Scenes compose a mesh with a setup (issue 13, goal 7): the mesh frame (mesh.h) every setup reads,
// pin modes on a mesh's own extent (a flat OBJ is not pinned whole), every setup on an OBJ, and the
// warning when every particle is pinned.
#include "clothtear/mesh.h"
#include "clothtear/scenes.h"
#include "clothtear/world.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

using namespace clothtear;
namespace fs = std::filesystem;

namespace {

constexpr int kNx = 13, kNy = 11;
constexpr double kW = 1.2, kH = 1.0;

// The built-in grid as an OBJ, upright or laid flat at y = 0.25 with its top edge away from a camera
// on +z (as a plane exported from a modeller lies).
std::string gridObj(const std::string& name, bool flat) {
    MeshData m = makeGridMesh(kNx, kNy, kW, kH);
    if (flat)
        for (Vec3d& p : m.positions) p = Vec3d(p.x(), 0.25, -p.y());
    const fs::path path = fs::temp_directory_path() / ("clothtear_compose_" + name + ".obj");
    EXPECT_TRUE(saveObj(m, path.string()));
    return path.string();
}

std::vector<Index> pinnedOf(const World& w) {
    std::vector<Index> pinned;
    for (Index p = 0; p < w.cloth.particleCount(); ++p)
        if (w.cloth.pinned(p)) pinned.push_back(p);
    return pinned;
}

World load(const std::string& scene, std::vector<std::string> sets = {}) {
    World w;
    EXPECT_EQ(loadScene(w, scene, sets), "") << scene;
    return w;
}

} // namespace

TEST(MeshFrame, BuiltInMeshGetsTheWorldAxesExactly) {
    const MeshData m = makeGridMesh(kNx, kNy, kW, kH);
    const MeshFrame f = meshFrame(m.positions);
    EXPECT_EQ(f.right, Vec3d::UnitX());
    EXPECT_EQ(f.up, Vec3d::UnitY());
    EXPECT_EQ(f.normal, Vec3d::UnitZ());
    EXPECT_NEAR(f.width(), kW, 1e-12);
    EXPECT_NEAR(f.height(), kH, 1e-12);
    EXPECT_NEAR(f.maxV, 0.5 * kH, 1e-12);
}

TEST(MeshFrame, FlatMeshHasItsFarEdgeOnTopAndAnyPlaneItsOwnAxes) {
    MeshData m = makeGridMesh(kNx, kNy, kW, kH);
    std::vector<Vec3d> flat, turned;
    // A plane turned 30 deg about y and tilted 20 deg back: still upright enough to hang.
    const Eigen::Matrix3d R = (Eigen::AngleAxisd(0.5236, Vec3d::UnitY()) * Eigen::AngleAxisd(-0.349, Vec3d::UnitX()))
                                  .toRotationMatrix();
    for (const Vec3d& p : m.positions) flat.push_back(Vec3d(p.x(), 2.0, -p.y())), turned.push_back(R * p + Vec3d(3, 1, 0));
    const MeshFrame f = meshFrame(flat);
    EXPECT_EQ(f.normal, Vec3d::UnitY());
    EXPECT_EQ(f.up, -Vec3d::UnitZ());
    EXPECT_EQ(f.right, Vec3d::UnitX());
    EXPECT_NEAR(f.height(), kH, 1e-12);
    const MeshFrame t = meshFrame(turned);
    EXPECT_NEAR(t.normal.dot(R * Vec3d::UnitZ()), 1.0, 1e-9);
    EXPECT_NEAR(t.width(), kW, 1e-9); // the plane's own extent, not its bounding box
    EXPECT_NEAR(t.height(), kH, 1e-9);
    EXPECT_NEAR(t.right.y(), 0.0, 1e-9); // up is the in-plane direction nearest +y: right is level
}

// The same grid upright, flat (an OBJ from a modeller) and built in: every pin mode pins the same
// particles (the OBJ keeps the grid's vertex order), never all of them.
TEST(SceneCompose, PinModesUseTheMeshsOwnExtent) {
    const std::string upright = gridObj("upright", false), flat = gridObj("flat", true);
    for (const char* pin : {"top", "corners", "sides", "left"}) {
        const std::vector<std::string> sets = {"cloth.resolution_x=" + std::to_string(kNx),
                                               "cloth.resolution_y=" + std::to_string(kNy), "cloth.width=1.2",
                                               "cloth.height=1", std::string("cloth.pin=") + pin};
        const std::vector<Index> grid = pinnedOf(load("curtain", sets));
        ASSERT_FALSE(grid.empty()) << pin;
        ASSERT_LT(grid.size(), size_t(kNx * kNy)) << pin;
        EXPECT_EQ(pinnedOf(load("obj:" + upright, sets)), grid) << pin;
        EXPECT_EQ(pinnedOf(load("obj:" + flat, sets)), grid) << pin << " on the flat OBJ";
    }
}

// Every setup runs on an OBJ; the pull's hand holds the same particles as on the built-in grid and
// pulls in the mesh's plane; the ball is thrown along the mesh's normal at its middle.
TEST(SceneCompose, EverySetupRunsOnAnObjAndReadsItsFrame) {
    const std::string flat = gridObj("flat_setups", true);
    for (const SceneDef& s : allScenes()) {
        World w = load(composeSceneName(s.name, flat));
        EXPECT_EQ(w.settings.cloth.mesh, MeshType::Obj) << s.name;
        for (int f = 0; f < 3; ++f) w.step();
        EXPECT_TRUE(w.finite) << s.name;
    }
    const std::vector<std::string> gridSets = {"cloth.resolution_x=" + std::to_string(kNx),
                                               "cloth.resolution_y=" + std::to_string(kNy), "cloth.width=1.2",
                                               "cloth.height=1"};
    const World grid = load("pull", gridSets), onFlat = load("pull:obj:" + flat);
    ASSERT_EQ(grid.drivers.size(), 1u);
    ASSERT_EQ(onFlat.drivers.size(), 1u);
    EXPECT_EQ(onFlat.drivers[0].particles, grid.drivers[0].particles);
    // Straight "down" in a flat mesh's plane is towards the camera, +z.
    const Vec3 v = onFlat.drivers[0].velocity;
    EXPECT_NEAR(v.z(), onFlat.settings.scene.pullSpeed, 1e-5f);
    EXPECT_NEAR(v.y(), 0.f, 1e-6f);

    const World ball = load("ball-r0.5-v3:obj:" + flat);
    ASSERT_EQ(ball.balls.size(), 1u);
    const Ball& b = ball.balls[0];
    EXPECT_NEAR(b.x.y(), 0.25f + b.radius + 0.05f, 1e-5f); // above the flat cloth
    EXPECT_LT(b.v.y(), 0.f);                                // thrown down onto it
    EXPECT_NEAR(b.v.norm(), ball.settings.scene.ballSpeed, 1e-5f);
}

TEST(SceneCompose, NamesParseAndBadOnesSayWhy) {
    Result<SceneName> n = parseSceneName("pull:obj:a/b:c.obj");
    ASSERT_TRUE(n.ok()) << n.error;
    EXPECT_STREQ(n.value.setup->name, "pull");
    EXPECT_EQ(n.value.objPath, "a/b:c.obj");
    n = parseSceneName("obj:x.obj");
    ASSERT_TRUE(n.ok());
    EXPECT_STREQ(n.value.setup->name, "curtain");
    EXPECT_EQ(composeSceneName("tension", "m.obj"), "tension:obj:m.obj");
    EXPECT_EQ(composeSceneName("tension", ""), "tension");
    EXPECT_NE(parseSceneName("nope:obj:x.obj").error.find("unknown scene 'nope'"), std::string::npos);
    EXPECT_NE(parseSceneName("pull:obj:").error.find("no OBJ path"), std::string::npos);
    World w;
    EXPECT_NE(loadScene(w, "pull:obj:/no/such/file.obj").find("/no/such/file.obj"), std::string::npos);
}

TEST(SceneCompose, EveryParticlePinnedIsWarnedAbout) {
    EXPECT_EQ(sceneWarnings(load("curtain", {"cloth.resolution_x=8", "cloth.resolution_y=8"})), "");
    const std::string warning = sceneWarnings(
        load("curtain", {"cloth.resolution_x=2", "cloth.resolution_y=8", "cloth.pin=sides"}));
    EXPECT_NE(warning.find("every particle is pinned"), std::string::npos) << warning;
}
