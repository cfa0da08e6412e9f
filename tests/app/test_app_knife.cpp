// The knife tool without a window: a stroke drawn frame by frame across the curtain cuts it in two
// as it goes; the stroke is read in rest space, so it cuts the same material wherever the cloth is.
#include "tools.h"

#include "clothtear/pieces.h"
#include "clothtear/scenes.h"

#include <gtest/gtest.h>

using namespace clothtear;
using namespace clothtear::app;

namespace {

View frontView() {
    OrbitCamera cam;
    cam.target = Vec3(0, 0, 0);
    cam.yaw = 0.f;
    cam.pitch = 0.f;
    cam.distance = 4.f;
    return makeView(cam, 1280.f, 720.f);
}

Vec2 pixelOf(const View& v, const Vec3& p) {
    Vec2 w;
    EXPECT_TRUE(projectToWindow(v.viewProjection, p, v.width, v.height, w));
    return w;
}

} // namespace

// From above the curtain (2 m x 2 m, pinned at the top) to below it at x = 0.3 m, 40 frames with the
// cloth simulated in between: halfway it is cut but still one piece; at the end two pieces of 1.3
// and 0.7 of the width (the stroke reached back to the top edge and on past the bottom edge).
TEST(AppKnife, AStrokeAcrossTheCurtainCutsItInTwoAsItGoes) {
    World w;
    ASSERT_EQ(loadScene(w, "curtain"), "");
    const double area = w.cloth.totalRestArea(), uv = w.cloth.totalUvArea();
    const View view = frontView();
    KnifeState knife;
    knifeBegin(w, knife, view, pixelOf(view, Vec3(0.3f, 1.3f, 0.f)));
    EXPECT_TRUE(knife.held);
    EXPECT_FALSE(knife.onCloth) << "starts above the cloth";
    size_t halfway = 0;
    for (int f = 1; f <= 40; ++f) {
        knifeMove(w, knife, view, pixelOf(view, Vec3(0.3f, 1.3f - 2.6f * float(f) / 40.f, 0.f)));
        EXPECT_EQ(validateCloth(w.cloth, area, uv), "") << "frame " << f;
        if (f == 20) {
            halfway = knife.springsCut;
            EXPECT_EQ(findPieces(w.cloth).size(), 1u) << "not through yet";
        }
        w.step();
    }
    knifeEnd(knife);
    EXPECT_FALSE(knife.held);
    EXPECT_GT(halfway, 10u) << "it cuts as it goes";
    EXPECT_GT(knife.springsCut, halfway);
    const std::vector<Piece> pieces = findPieces(w.cloth);
    ASSERT_EQ(pieces.size(), 2u);
    EXPECT_NEAR(pieces[0].restArea, 2.6, 0.05); // the cloth sags a little under the cursor
    EXPECT_NEAR(pieces[1].restArea, 1.4, 0.05);
    EXPECT_EQ(w.tearLog.counts[int(TearMode::Knife)], knife.springsCut);
}

// The cloth moved 0.5 m to the right: the same stroke on screen, 0.5 m further right, cuts the same
// material (rest u = 0.3) through the hit triangle's barycentric coordinates.
TEST(AppKnife, TheStrokeFollowsTheMaterialNotTheScreen) {
    World w;
    ASSERT_EQ(loadScene(w, "curtain"), "");
    for (Vec3& x : w.cloth.x) x += Vec3(0.5f, 0.f, 0.f);
    const View view = frontView();
    Vec2d rest;
    ASSERT_TRUE(restPointUnder(w, view, pixelOf(view, Vec3(0.8f, 0.2f, 0.f)), rest));
    EXPECT_NEAR(rest.x(), 0.3, 1e-3);
    EXPECT_NEAR(rest.y(), 0.2, 1e-3);
    EXPECT_FALSE(restPointUnder(w, view, pixelOf(view, Vec3(-0.8f, 0.2f, 0.f)), rest)) << "left of the moved cloth";
    KnifeState knife;
    knifeBegin(w, knife, view, pixelOf(view, Vec3(0.8f, 0.5f, 0.f)));
    EXPECT_TRUE(knife.onCloth);
    knifeMove(w, knife, view, pixelOf(view, Vec3(0.8f, 0.5f, 0.f))); // not moved: nothing
    EXPECT_EQ(knife.springsCut, 0u);
    knifeMove(w, knife, view, pixelOf(view, Vec3(0.8f, -0.5f, 0.f)));
    EXPECT_GT(knife.springsCut, 15u);
    for (const TearEvent& e : w.tearLog.events) EXPECT_NEAR(e.restPos.x(), 0.3, 0.01);
    EXPECT_EQ(findPieces(w.cloth).size(), 1u) << "a slit inside";
    EXPECT_STREQ(toolName(Tool::Knife), "Knife");
}
