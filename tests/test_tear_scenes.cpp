// The thesis ball experiments (Onal 4.1) and the pull/tension scenes, checked through the headless
// runner's JSON report (the same path a user takes).
#include "tear_axis.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

// threads > 0: the run's OpenMP threads (the state depends on the thread count, test_determinism.cpp).
// The report's file is named by the process too: ctest runs two tests at once, and two of them may run
// the same scene with other thread counts.
nlohmann::json runScene(const std::string& scene, double seconds, const std::string& extra = "", int threads = 0) {
    const std::string env = threads > 0 ? "OMP_NUM_THREADS=" + std::to_string(threads) + " " : "";
    const std::string out = ::testing::TempDir() + "tear_scene_" + std::to_string(getpid()) + "_" +
                            std::to_string(std::hash<std::string>{}(env + scene + extra)) + ".json";
    const std::string cmd = env + std::string(CLOTHTEAR_BINARY) + " --headless --scene " + scene + " --seconds " +
                            std::to_string(seconds) + " " + extra + " --json " + out + " > /dev/null";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    std::ifstream in(out);
    nlohmann::json j;
    in >> j;
    return j;
}

struct BallCase {
    const char* scene;
    bool tears;
};

// The thesis outcomes (Onal 4.1, Table 4.1) with the documented default cloth.
const BallCase kCases[] = {
    {"ball-r0.5-v3", true},   {"ball-r1-v3-low", false}, {"ball-r1-v3-high", true},
    {"ball-r2-v3", false},    {"ball-r2-v10", true},
};

} // namespace

// Each outcome must hold with the default tear threshold and with it 10% lower and 10% higher (the
// outcome is not a knife-edge), with texture integrity and mass conservation through all of it.
TEST(BallExperiments, OutcomesMatchTheThesisWithinTenPercentOfTheThreshold) {
    const double threshold = 0.35; // tearClothConfig
    for (const BallCase& c : kCases)
        for (double f : {0.9, 1.0, 1.1}) {
            const std::string set = "--set tear.threshold=" + std::to_string(threshold * f);
            const nlohmann::json r = runScene(c.scene, 2.5, set);
            const std::string where = std::string(c.scene) + " " + set;
            ASSERT_TRUE(r["finite"].get<bool>()) << where;
            EXPECT_EQ(r["tears_total"].get<uint64_t>() > 0, c.tears) << where << " tears: " << r["tears"];
            EXPECT_NEAR(r["rest_area"].get<double>(), 36.0, 36.0 * 1e-9) << where;
            EXPECT_NEAR(r["uv_area"].get<double>(), 1.0, 1e-9) << where;
            EXPECT_NEAR(r["total_mass"].get<double>(), double(0.2f) * 36.0, 36.0 * 1e-9) << where;
            // No sliver springs: a basic tear never halves a spring below minSplitRest, so strains
            // stay near the limit instead of exploding on vanishing rest lengths.
            EXPECT_LT(r["max_strain"].get<double>(), 1.0) << where;
        }
}

// Issue 12: the outcomes at twice the thesis resolution (96 x 96), where the unconverged solve
// tore the ball that must slide over (ball-r2-v3: 156 tears). Four that fit the suite's time;
// ball-r2-v10 (tears) takes 9 s here and holds too (bench/README.md, "Does the cloth hold?").
// ball-r2-v3 tore at 96 a side until a tear where no hand pulls was read over tear.gauge_length
// (7 tears on one thread, along the bottom edge the ball rolled onto; bench/README.md, "A ball
// tears by metres of stretch").
TEST(BallExperiments, OutcomesHoldAtTwiceTheResolution) {
    for (const BallCase& c : {BallCase{"ball-r0.5-v3", true}, BallCase{"ball-r1-v3-low", false},
                              BallCase{"ball-r1-v3-high", true}, BallCase{"ball-r2-v3", false}}) {
        const nlohmann::json r = runScene(c.scene, 2.5, "--set cloth.resolution_x=96 --set cloth.resolution_y=96");
        ASSERT_TRUE(r["finite"].get<bool>()) << c.scene;
        EXPECT_EQ(r["tears_total"].get<uint64_t>() > 0, c.tears) << c.scene << " tears: " << r["tears_total"];
        EXPECT_NEAR(r["uv_area"].get<double>(), 1.0, 1e-9) << c.scene;
    }
}

// At three times the thesis resolution (144 x 144, spacing 0.042 m, a third of tear.gauge_length)
// the balls that must tear still do. An earlier gauge (the strain averaged over the triangles within
// L, with springs held at the threshold) stopped both from tearing at 96 and 144 once L passed the
// spacing (bench/README.md, "Five probes of the tear test"): a ball could then never stretch a gauge
// to the threshold. Here a spring under a ball is held up to its gauge's stretch (heldLength).
// ball-r2-v3 holds at 144 at the default gravity, but 3 of 4 runs with gravity changed by 1e-5 to
// 1e-4 tear (163-316 tears): not asserted (bench/README.md, "A ball tears by metres of stretch").
TEST(BallExperiments, TheBallsThatTearStillTearAtThreeTimesTheResolution) {
    for (const BallCase& c : {BallCase{"ball-r1-v3-high", true}, BallCase{"ball-r2-v10", true}}) {
        const nlohmann::json r = runScene(c.scene, 2.0, "--set cloth.resolution_x=144 --set cloth.resolution_y=144");
        ASSERT_TRUE(r["finite"].get<bool>()) << c.scene;
        EXPECT_EQ(r["tears_total"].get<uint64_t>() > 0, c.tears) << c.scene << " tears: " << r["tears_total"];
        EXPECT_NEAR(r["uv_area"].get<double>(), 1.0, 1e-9) << c.scene;
        EXPECT_NEAR(r["rest_area"].get<double>(), 36.0, 36.0 * 1e-9) << c.scene;
    }
}

TEST(TearScenes, PullAndTensionTearAndStayFinite) {
    for (const char* scene : {"pull", "tension --set tension.notch=1"}) {
        const nlohmann::json r = runScene(scene, 3.0, "--set tear.validate=1");
        ASSERT_TRUE(r["finite"].get<bool>()) << scene;
        EXPECT_GT(r["tears_total"].get<uint64_t>(), 0u) << scene;
        EXPECT_EQ(r["tear_events"].size(), r["tears_total"].get<size_t>()) << scene;
        EXPECT_EQ(r["validation_error"].get<std::string>(), "") << scene;
        EXPECT_NEAR(r["rest_area"].get<double>(), 36.0, 36.0 * 1e-9) << scene;
        EXPECT_NEAR(r["uv_area"].get<double>(), 1.0, 1e-9) << scene;
    }
}

// Onal 4.2: pulled straight down at the bottom centre, the cloth tears next to the hand (a 0.3 m
// patch, grab.radius: the first tear within 0.5 m of its rim) and the cut runs across the pull
// (horizontally: its extent in x exceeds its extent in y).
TEST(TearScenes, PullTearsNextToTheGrabAcrossThePull) {
    const nlohmann::json r = runScene("pull", 4.0, "--set pull.angle=0");
    ASSERT_TRUE(r["finite"].get<bool>());
    const nlohmann::json& ev = r["tear_events"];
    ASSERT_GE(ev.size(), 3u);
    const double grabY = -3.0; // bottom edge of the 6 m cloth
    double xMin = 1e9, xMax = -1e9, yMin = 1e9, yMax = -1e9;
    for (const auto& e : ev) {
        const double x = e["rest"][0].get<double>(), y = e["rest"][1].get<double>();
        xMin = std::min(xMin, x), xMax = std::max(xMax, x), yMin = std::min(yMin, y), yMax = std::max(yMax, y);
    }
    const double x0 = ev[0]["rest"][0].get<double>(), y0 = ev[0]["rest"][1].get<double>();
    const double hand = 0.3; // the pull scene's grab.radius (scenes.cpp)
    EXPECT_LT(std::hypot(x0, y0 - grabY), hand + 0.5) << "first tear at " << x0 << ", " << y0;
    EXPECT_GT(xMax - xMin, 2.0 * (yMax - yMin)) << "x " << xMin << ".." << xMax << ", y " << yMin << ".." << yMax;
}

// Issue 13, the hand has a size: the pull holds a 0.3 m patch (grab.radius), not one particle, so
// the rip does not depend on the resolution. Holding one particle, it tore out alone (3 tears at 40
// and at 80 a side). At 40 and 80 a side, pulled straight down or at a slant (below): the rip starts
// at the same time (within 10 %), runs horizontally (its principal axis within 20 deg) and is over
// 1 m long. Straight down and at 30 deg it also has about the same length in metres (within 25 %)
// and leaves the same pieces: the sheet and what the hand tore out, no scraps (the smallest piece is
// over 0.1 m^2, some ten rest triangles at 40).
//
// Not asserted at 60 deg: whether the hand's patch comes out within the 4 s, and so the pieces and
// the rip's length. At 80 a side they change with the rounding of the force sums: pull.speed 0.5
// +- 1e-4, one or two threads, give 1, 2 or 3 pieces (extra pieces of 0.02-0.53 m^2) and 1.07-1.81
// m of rip, on the spring loop before the spring groups as well as with them (bench/README.md, "The
// spring groups"). At 0 and 30 deg every one of those runs gives the same rip.
namespace {
struct Rip {
    double firstTime = 0, axisDeg = 0, length = 0;
    size_t tears = 0, pieces = 0;
    double smallestPiece = 0; // m^2
};
Rip ripOf(const nlohmann::json& r) {
    Rip rip;
    const nlohmann::json& ev = r["tear_events"];
    rip.tears = ev.size();
    rip.pieces = r["pieces"]["count"].get<size_t>();
    rip.smallestPiece = r["pieces"]["smallest_area"].get<double>();
    if (ev.empty()) return rip;
    rip.firstTime = ev[0]["time"].get<double>();
    const TearAxis axis = tearAxisOf(ev);
    const double mx = axis.mx, my = axis.my, th = axis.theta;
    double lo = 1e9, hi = -1e9;
    for (const auto& e : ev) {
        const double p = (e["rest"][0].get<double>() - mx) * std::cos(th) + (e["rest"][1].get<double>() - my) * std::sin(th);
        lo = std::min(lo, p), hi = std::max(hi, p);
    }
    rip.axisDeg = std::abs(th) * 180.0 / M_PI; // 0: horizontal
    rip.length = hi - lo;
    return rip;
}
} // namespace

// Pulled straight down and at 30 and 60 deg towards the side, the rip is the same at 40 and 80 a
// side and runs horizontally. Horizontal is across the tension the hand puts into the sheet, not
// across the hand's velocity: the hand is driven at a set velocity, and the force it needs points
// to where the sheet holds it back, the pinned top edge. The principal stretch of the sheet round
// the hand at the first tear points 68-87 deg from horizontal at 30 and 60 deg (rest-frame
// deformation gradients of the triangles within 0.45-1 m of the hand, at 40 and 80), so the rip
// across it is within about 20 deg of horizontal. Pulled sideways (90 deg): the next test.
// The margin at 30 deg is thin: at 40 a side the hand's flap comes free at 3.88-3.90 s (3.48 at one
// of four speeds), 0.1 s before the 4 s read here, where at 80 it is out by 2.5-3.3 s. A change that
// holds the coarse sheet's hand a little longer (the hand's passes spread over the frame did: 3.86-
// 4.66 s) fails here with 1 piece against 2 (bench/README.md, "The hand's patch at 40 a side").
TEST(TearScenes, PullRipIsTheSameAtTwoResolutions) {
    for (int angle : {0, 30, 60}) {
        Rip rips[2];
        const int res[2] = {40, 80};
        for (int k = 0; k < 2; ++k) {
            const std::string r = std::to_string(res[k]);
            rips[k] = ripOf(runScene("pull", 4.0, "--set pull.angle=" + std::to_string(angle) + " --set cloth.resolution_x=" + r +
                                                      " --set cloth.resolution_y=" + r));
            ASSERT_GE(rips[k].tears, 5u) << angle << " deg at " << res[k];
            EXPECT_LT(std::min(rips[k].axisDeg, 180.0 - rips[k].axisDeg), 20.0) << angle << " deg at " << res[k];
            EXPECT_GT(rips[k].length, 1.0) << angle << " deg at " << res[k]; // a rip, not the hand torn out (0.6 m across)
            if (angle < 60) {
                EXPECT_GT(rips[k].smallestPiece, 0.1) << angle << " deg at " << res[k];
            }
        }
        EXPECT_NEAR(rips[1].firstTime, rips[0].firstTime, 0.1 * rips[0].firstTime) << angle << " deg";
        if (angle >= 60) continue;
        EXPECT_EQ(rips[1].pieces, rips[0].pieces) << angle << " deg";
        EXPECT_NEAR(rips[1].length, rips[0].length, 0.25 * std::max(rips[0].length, rips[1].length)) << angle << " deg";
    }
}

// Pulled sideways (90 deg) the sheet goes taut between the hand and the far end of the pinned edge
// (on the 6 m sheet at about 2.6 s the hand is 1.1 x its rest distance from that corner) and the
// stretch round the hand leans to 51-57 deg: the rip runs across it, at about 45 deg, and starts near
// that moment, at 40 and at 80 a side alike, on the 6 m grid, on a 3 m one and on the 6 m irregular
// mesh. With the limit's passes under a moving hand a fixed count (12), not a share of the depth
// (limit.cpp, passCap), the hand's pull reached twice as far in metres at 40 as at 80: the 6 m sheet
// at 40 tore 1 s later, at 13 deg, the 3 m one at 13 deg too (bench/README.md, "The hand's passes by
// depth"). The rip's length on the 6 m sheet: the next test. On one thread, so that every machine
// checks the same runs: the rips move with the round-off of the thread count, and on three or four
// threads the 3 m sheet's axes at 40 and 80 are 11-14 deg apart and a 2 m^2 part comes off at 40
// only. The first tears: the 6 m sheet at 40 a side tears at 2.92-2.94 s, later than at 80 (its 10
// sub-steps, `time.substeps`' floor; at the guard's 7 it tears at 2.46-2.53 s: bench/README.md, "The
// sideways rip again"), and at 80 at 2.46-2.57 s with round-off (gravity 1e-6 stronger: 2.46, 16 %
// before 40's): within 20 %.
TEST(TearScenes, PulledSidewaysTheRipLeansTheSameWayAtTwoResolutions) {
    for (const char* sheet : {"", " --set cloth.width=3 --set cloth.height=3", " --set cloth.mesh=irregular"}) {
        Rip rips[2];
        const int res[2] = {40, 80};
        for (int k = 0; k < 2; ++k) {
            const std::string r = std::to_string(res[k]);
            rips[k] = ripOf(runScene("pull", 4.0,
                                     "--set pull.angle=90 --set cloth.resolution_x=" + r + " --set cloth.resolution_y=" + r + sheet,
                                     1));
            ASSERT_GE(rips[k].tears, 5u) << res[k] << sheet;
            EXPECT_GT(rips[k].axisDeg, 30.0) << res[k] << sheet;
            EXPECT_LT(rips[k].axisDeg, 60.0) << res[k] << sheet;
            EXPECT_GT(rips[k].length, 1.0) << res[k] << sheet;
        }
        EXPECT_NEAR(rips[1].axisDeg, rips[0].axisDeg, 10.0) << sheet;
        EXPECT_NEAR(rips[1].firstTime, rips[0].firstTime, 0.2 * std::max(rips[0].firstTime, rips[1].firstTime)) << sheet;
        EXPECT_EQ(rips[1].pieces, rips[0].pieces) << sheet;
    }
}

// Issue 13 goal 1, the rip's length: pulled sideways for 5 s the 6 m sheet's rip is about as long in
// metres at 40, 80 and 160 a side (the median of three hand speeds 1e-4 m/s apart within 25 % of the
// longest), leans the same way and leaves one piece. Reading the tension across the tense spring the
// medians were 1.85 / 2.10 / 3.44 m and at 80 a side one run gave 1.5 m and the next 3.5 m; across
// the fabric's tension within tear.tip_radius (tear_tension.h) they are 2.62 / 3.24 / 3.35, each
// resolution's runs within 0.7 m of each other (bench/README.md, "The tear tip reads the fabric's
// tension"). At 40 the rip starts 0.4 s later (its 10 sub-steps, the floor; the test above), which is
// most of what it lacks. On one thread, as the test above.
TEST(TearScenes, PulledSidewaysTheRipIsAsLongAtEveryResolution) {
    const int res[3] = {40, 80, 160};
    double length[3] = {}, axis[3] = {};
    for (int k = 0; k < 3; ++k) {
        std::vector<double> lengths, axes;
        for (const char* speed : {"0.4999", "0.5", "0.5001"}) {
            const std::string n = std::to_string(res[k]);
            const Rip rip = ripOf(runScene("pull", 5.0,
                                           "--set pull.angle=90 --set pull.speed=" + std::string(speed) +
                                               " --set cloth.resolution_x=" + n + " --set cloth.resolution_y=" + n,
                                           1));
            ASSERT_GE(rip.tears, 5u) << res[k] << ", " << speed << " m/s";
            EXPECT_EQ(rip.pieces, 1u) << res[k] << ", " << speed << " m/s: the rip runs in, nothing comes off";
            lengths.push_back(rip.length);
            axes.push_back(rip.axisDeg);
        }
        std::sort(lengths.begin(), lengths.end());
        std::sort(axes.begin(), axes.end());
        length[k] = lengths[1], axis[k] = axes[1];
        EXPECT_GT(length[k], 2.0) << res[k] << ": a rip that keeps growing, not the hand's rim";
    }
    const double longest = *std::max_element(length, length + 3);
    for (int k = 0; k < 3; ++k) {
        EXPECT_GT(length[k], 0.75 * longest) << res[k] << " a side: " << length[0] << " / " << length[1] << " / "
                                             << length[2] << " m at 40 / 80 / 160";
        EXPECT_NEAR(axis[k], axis[1], 10.0) << res[k] << " a side, degrees from horizontal";
    }
}

namespace {
// The pull on the 6 m sheet at `res` a side for 4 s (`extra`: more --set options, `threads` as
// runScene's) tears, leaves no piece under five rest triangles of the mesh and loses no area.
void expectPullLeavesNoScraps(int angle, int res, const std::string& extra, int threads, const std::string& where) {
    const std::string r = std::to_string(res);
    const nlohmann::json j = runScene("pull", 4.0,
                                      "--set pull.angle=" + std::to_string(angle) + " --set cloth.resolution_x=" + r +
                                          " --set cloth.resolution_y=" + r + extra,
                                      threads);
    const Rip rip = ripOf(j);
    const double spacing = 6.0 / (res - 1), restTriangle = 0.5 * spacing * spacing;
    EXPECT_GE(rip.tears, 5u) << where << ": the pull tears";
    EXPECT_GT(rip.smallestPiece, 5 * restTriangle) << where << ": " << rip.pieces << " pieces";
    double total = 0;
    for (double a : j["pieces"]["areas"].get<std::vector<double>>()) total += a;
    EXPECT_NEAR(total, 36.0, 1e-6) << where << ": every rest m^2 of the 6 m sheet is in one of its pieces";
}
} // namespace

// Issue 13 goal 2, no confetti: pulled at a slant or sideways, the hand tears the sheet and may tear
// its patch out, but no piece of a few rest triangles comes loose. Before the drivers' cap a 128 a
// side drag left a two-triangle scrap; a one-point split that sets loose a fan of one or two
// triangles would show here as a piece of under 0.01 m^2 (a rest triangle is 0.012 m^2 at 40 and
// 0.003 at 80). The bound is five rest triangles: at 80 a side, 60 and 90 deg, a piece of 0.02-0.1
// m^2 (8-35 triangles) comes off in some runs and not in others, with the rounding of the force sums
// (pull.speed 0.5 +- 1e-4, one or two threads; on the spring loop before the spring groups too:
// bench/README.md, "The spring groups"), which a bound of 0.1 m^2 turned into a coin toss. Since the
// hand's passes are a share of the depth, one such piece (0.027 m^2, 9 triangles) comes off at 60 deg
// and 80 a side on four threads: the area is checked over every piece, not the sheet and the patch.
TEST(TearScenes, SlantedPullsLeaveNoScraps) {
    for (int angle : {30, 60, 90})
        for (int res : {40, 80})
            expectPullLeavesNoScraps(angle, res, "", 0, std::to_string(angle) + " deg at " + std::to_string(res));
}

// The same bound whatever the round-off: on one thread and with hand speeds 1e-4 m/s apart, which
// tear differently (other pieces, other places). While a one-point split kept on only fans of under
// 1.5 squared mean rest lengths (3.9 rest triangles of a grid), the 60 deg pull at 80 a side set
// loose a piece of 0.012 m^2 (4.0 triangles, under the bound of five) in 3 of 21 hand speeds from
// 0.499 to 0.501 m/s on one thread, 0.5 among them, though not on two threads, where the test above
// runs (bench/README.md, "No confetti: the bound the tests hold"). Now the split keeps on up to 2.0
// (5.2 triangles): minLooseArea, cloth.h.
TEST(TearScenes, SlantedPullsLeaveNoScrapsWhateverTheRoundOff) {
    for (int angle : {60, 90})
        for (const char* speed : {"0.4991", "0.5", "0.5005"})
            expectPullLeavesNoScraps(angle, 80, std::string(" --set pull.speed=") + speed, 1,
                                     std::to_string(angle) + " deg at 80, " + speed + " m/s, one thread");
}
