// The ball tool from the start camera (issue 13, goal 5): the default throw reaches the cloth, and a
// ball that tears through passes or stops; it never comes back through the cloth.
#include "camera.h"
#include "tools.h"

#include "clothtear/pieces.h"
#include "clothtear/scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

using namespace clothtear;
using namespace clothtear::app;

namespace {

struct Flight {
    bool aimed = false;
    float neededSpeed = 0;
    bool crossed = false;   // the ball's centre went behind the cloth
    bool cameBack = false;  // ... and later in front of it again
    float backSpeed = 0;    // the fastest it moved back towards the camera after touching, m/s
    int tears = 0;
    float startDistance = 0, endDistance = 0; // of the camera framing the world (V) before and after
    float endDistanceWithoutBall = 0;         // framing the same world with its ball taken out
    float endDistanceLargestPiece = 0;        // ... and with only its largest piece of cloth
    float farPieceShare = 0; // largest share of the rest area in a piece centred 2 m or more from the largest piece
};

Flight throwFromStartCamera(const std::string& scene, std::vector<std::string> sets, int frames) {
    World w;
    EXPECT_EQ(loadScene(w, scene, sets), "") << scene;
    OrbitCamera cam;
    frameWorld(cam, w);
    const View view = makeView(cam, 1280.f, 720.f);
    Vec3 mid = Vec3::Zero();
    for (const Vec3& x : w.cloth.x) mid += x;
    mid /= float(w.cloth.particleCount());
    Vec2 px;
    EXPECT_TRUE(projectToWindow(view.viewProjection, mid, view.width, view.height, px));
    const Throw t = throwBall(w, view, px);
    Flight f;
    f.aimed = t.aimed;
    f.neededSpeed = t.neededSpeed;
    w.balls.push_back(t.ball);
    const Vec3 towardsCamera = (cam.position() - mid).normalized();
    bool touched = false;
    for (int i = 0; i < frames; ++i) {
        w.step();
        const Ball& b = w.balls[0];
        const float side = (b.x - mid).dot(towardsCamera);
        for (const Vec3& x : w.cloth.x) touched = touched || (x - b.x).norm() < b.radius + 0.05f;
        if (side < 0.f) f.crossed = true;
        if (f.crossed && side > b.radius) f.cameBack = true;
        if (touched) f.backSpeed = std::max(f.backSpeed, b.v.dot(towardsCamera));
    }
    f.tears = int(w.tearLog.total());
    f.startDistance = cam.distance;
    OrbitCamera after;
    frameWorld(after, w);
    f.endDistance = after.distance;
    World noBall = w;
    noBall.balls.clear();
    OrbitCamera without;
    frameWorld(without, noBall);
    f.endDistanceWithoutBall = without.distance;
    {
        World largest = noBall;
        // Deleting renumbers triangles: the smallest piece goes, then the pieces are found again.
        for (std::vector<Piece> pieces = findPieces(largest.cloth); pieces.size() > 1; pieces = findPieces(largest.cloth))
            largest.deletePiece(std::min_element(pieces.begin(), pieces.end(), [](const Piece& a, const Piece& b) {
                                    return a.restArea < b.restArea;
                                })->firstTriangle);
        OrbitCamera only;
        frameWorld(only, largest);
        f.endDistanceLargestPiece = only.distance;
    }
    // The pieces (connected islands): rest area and mean position.
    const std::vector<Index> label = pieceLabels(w.cloth);
    const size_t n = w.cloth.particleCount();
    double total = 0;
    const std::vector<double> area = restAreaByLabel(w.cloth, label, total);
    std::vector<Vec3> sum(n, Vec3::Zero());
    std::vector<int> count(n, 0);
    for (Index p = 0; p < n; ++p)
        if (label[p] != kNone) sum[label[p]] += w.cloth.x[p], ++count[label[p]];
    Index main = 0;
    for (Index l = 0; l < n; ++l)
        if (area[l] > area[main]) main = l;
    const Vec3 mainAt = sum[main] / float(count[main]);
    for (Index l = 0; l < n; ++l)
        if (count[l] > 0 && l != main && (sum[l] / float(count[l]) - mainAt).norm() >= 2.f)
            f.farPieceShare = std::max(f.farPieceShare, float(area[l] / total));
    return f;
}

} // namespace

// From the camera the app starts with (frameWorld), at the cloth's middle, with the default speed: the throw is
// aimed (reaches), hits, and never comes back out through the cloth (issue 13 saw a ball tear through
// and fly back towards the camera). Two resolutions and two pinnings; a light and a heavy ball.
TEST(AppBallThrow, DefaultThrowFromTheStartCameraReachesAndNeverComesBack) {
    struct Case {
        const char* scene;
        int n;
        float mass;
    };
    for (const Case& c : {Case{"curtain", 32, 2.f}, Case{"curtain", 64, 2.f}, Case{"corners", 32, 10.f},
                          Case{"curtain", 32, 0.5f}}) {
        const std::string res = std::to_string(c.n);
        const Flight f = throwFromStartCamera(
            c.scene, {"cloth.resolution_x=" + res, "cloth.resolution_y=" + res, "ball.mass=" + std::to_string(c.mass)},
            80);
        const std::string what = std::string(c.scene) + " at " + res + ", " + std::to_string(c.mass) + " kg";
        EXPECT_TRUE(f.aimed) << what << ": needs " << f.neededSpeed << " m/s";
        EXPECT_GT(f.tears, 0) << what << ": the default throw tears";
        EXPECT_TRUE(f.crossed) << what << ": and goes through";
        EXPECT_FALSE(f.cameBack) << what;
        EXPECT_LT(f.backSpeed, 1.f) << what << ": m/s back towards the camera";
        // V frames the cloth and its pieces, not the ball that flew on (issue 13: V zoomed far out), nor
        // scraps: beyond what the torn cloth's largest piece itself needs (a punched disc left hanging
        // from the hole's rim by a strip: the 0.5 kg ball's curtain reaches 1.6 m below its hem), it
        // zooms out by half again only for a piece of 5 % of the cloth or more lying 2 m away (the disc
        // a ball punches out and carries to the ground: bench/README.md, "The fabric a ball stretches").
        EXPECT_NEAR(f.endDistance, f.endDistanceWithoutBall, 1e-3f * f.endDistanceWithoutBall) << what;
        if (f.farPieceShare < 0.05f) {
            EXPECT_LT(f.endDistance, 1.5f * std::max(f.startDistance, f.endDistanceLargestPiece)) << what;
        }
        std::printf("%s: %d tears, V at %.2f m (start %.2f), largest far piece %.1f %% of the cloth\n", what.c_str(),
                    f.tears, f.endDistance, f.startDistance, 100.f * f.farPieceShare);
    }
}

// Below the speed that reaches, the throw is not aimed and says what it needs (the app's toast).
TEST(AppBallThrow, TooSlowAThrowSaysWhatItNeeds) {
    const Flight f = throwFromStartCamera("curtain", {"ball.speed=3"}, 1);
    EXPECT_FALSE(f.aimed);
    EXPECT_GT(f.neededSpeed, 3.f);
    EXPECT_LT(f.neededSpeed, World().settings.scene.ballSpeed) << "the default reaches";
}
