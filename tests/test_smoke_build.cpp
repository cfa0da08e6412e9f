// Scene loading: every library scene builds and reports the counts its mesh implies.
#include "clothtear/scenes.h"

#include <gtest/gtest.h>

using namespace clothtear;

TEST(Scenes, EveryLibrarySceneLoadsAndHasConsistentCounts) {
    for (const SceneDef& def : allScenes()) {
        World w;
        ASSERT_EQ(loadScene(w, def.name), "") << def.name;
        const int nx = w.settings.cloth.resolutionX, ny = w.settings.cloth.resolutionY;
        if (w.settings.cloth.mesh == MeshType::Obj) continue;
        EXPECT_EQ(w.cloth.particleCount(), size_t(nx * ny)) << def.name;
        EXPECT_EQ(w.cloth.triangles.size(), size_t(2 * (nx - 1) * (ny - 1))) << def.name;
        // Euler: V - E + F = 1 for a disc.
        EXPECT_EQ(long(w.cloth.particleCount()) - long(w.cloth.springs.size()) + long(w.cloth.triangles.size()), 1) << def.name;
        // One bend-shear spring per interior edge: E - boundary edges.
        const long boundary = 2 * (nx - 1) + 2 * (ny - 1);
        EXPECT_EQ(long(w.cloth.bends.size()), long(w.cloth.springs.size()) - boundary) << def.name;
    }
}

TEST(Scenes, UnknownSceneIsRefusedWithTheNameInTheMessage) {
    World w;
    const std::string err = loadScene(w, "nope");
    EXPECT_NE(err.find("unknown scene 'nope'"), std::string::npos) << err;
}
