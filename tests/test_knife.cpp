// The knife (knife.h, World::cut): cuts along strokes in the mesh's rest frame on the grid, the
// irregular mesh and a flat OBJ-like mesh (an irregular mesh lying in the x-z plane, off the origin).
// Areas against the analytic split, pieces, the slit's length, strokes along edges and through
// particles, torn cloth, strokes that miss, refused strokes, random strokes with every invariant, and
// the cut cloth simulating on.
#include "clothtear/history.h"
#include "clothtear/knife.h"
#include "clothtear/pieces.h"
#include "clothtear/random.h"
#include "clothtear/state_hash.h"
#include "clothtear/world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace clothtear;

namespace {

constexpr double kWidth = 1.2, kHeight = 0.9, kSpacing = 0.05; // 25 x 19 particles

// The three meshes the knife must work on, all 1.2 m x 0.9 m with 5 cm spacing, pinned at the top.
World sheet(const std::string& kind) {
    World w;
    ClothSettings& c = w.settings.cloth;
    c.width = float(kWidth), c.height = float(kHeight), c.resolutionX = 25, c.resolutionY = 19;
    c.mesh = kind == "grid" ? MeshType::Grid : MeshType::Irregular;
    std::string err;
    if (kind == "obj") {
        // A plane as a modeller exports it: flat (normal +y), its top edge at -z, far from the origin.
        MeshData m = makeIrregularMesh(25, 19, kWidth, kHeight, 0.3, 7);
        for (Vec3d& p : m.positions) p = Vec3d(p.x() + 3.0, 0.5, -p.y() - 2.0);
        c.mesh = MeshType::Obj;
        err = w.rebuild(m);
    } else {
        err = w.rebuild();
    }
    EXPECT_EQ(err, "") << kind;
    return w;
}

const char* const kMeshes[] = {"grid", "irregular", "obj"};

double meanTriangleArea(const Cloth& c) { return c.totalRestArea() / double(c.triangles.size()); }

// Length of the cloth's border and torn edges in rest space: springs with one triangle.
double boundaryLength(const Cloth& c) {
    double sum = 0;
    for (Index s = 0; s < c.springs.size(); ++s)
        if (c.springTopo[s].tri[1] == kNone) sum += (c.rest[c.springs[s].a] - c.rest[c.springs[s].b]).norm();
    return sum;
}

// The particle whose rest position is nearest (u, v) in the frame (buildCloth numbers particles in
// the order triangles first use them, not by rows).
Index particleNear(const World& w, double u, double v) {
    Index best = 0;
    double bestD = 1e300;
    for (Index p = 0; p < w.cloth.particleCount(); ++p) {
        const double d = (Vec2d(w.restFrame.u(w.cloth.rest[p]), w.restFrame.v(w.cloth.rest[p])) - Vec2d(u, v)).norm();
        if (d < bestD) bestD = d, best = p;
    }
    return best;
}

double cross2(const Vec2d& a, const Vec2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// Every spring still joined (two triangles) that crosses the stroke does so within a tenth of its
// length of an end, or is shorter than the tear's floor allows to split (where the knife takes the
// end particle instead: knife.h): none is left joined across the stroke. The first offender or "".
std::string joinedAcross(const World& w, const std::vector<Vec2d>& stroke) {
    const Cloth& c = w.cloth;
    auto at = [&](Index p) { return Vec2d(w.restFrame.u(c.rest[p]), w.restFrame.v(c.rest[p])); };
    for (size_t i = 1; i < stroke.size(); ++i) {
        const Vec2d a = stroke[i - 1], d = stroke[i] - a;
        for (Index s = 0; s < c.springs.size(); ++s) {
            if (c.springTopo[s].tri[1] == kNone) continue;
            const Vec2d p = at(c.springs[s].a), e = at(c.springs[s].b) - p;
            const double den = cross2(d, e);
            if (std::abs(den) < 1e-12 * d.norm() * e.norm()) continue;
            const double u = cross2(p - a, e) / den, t = cross2(p - a, d) / den;
            const double snap = std::max(0.1, 0.5 * c.minSplitRest / c.springs[s].rest) + 1e-6;
            if (u > 1e-6 && u < 1 - 1e-6 && t > snap && t < 1 - snap)
                return "spring " + std::to_string(s) + " joined across segment " + std::to_string(i) + " at t " +
                       std::to_string(t);
        }
    }
    return {};
}

// A cut with the checks every cut gets: accepted, invariants (areas and UV area as at the start),
// one Knife event per spring cut, nothing joined across the stroke. Segment by segment, each checked
// when it is cut (a later segment may refine the cloth near an earlier one's crossings, within the
// band where those went through a particle), which cuts the same as the whole polyline at once
// (cutAlong cuts segment by segment; a corner is a particle both share).
CutResult cutChecked(World& w, const std::vector<Vec2d>& stroke, double area0, double uv0, const std::string& what) {
    CutResult sum;
    for (size_t i = 1; i < stroke.size(); ++i) {
        const std::vector<Vec2d> segment = {stroke[i - 1], stroke[i]};
        const uint64_t eventsBefore = w.tearLog.counts[int(TearMode::Knife)];
        const CutResult r = w.cut(segment);
        EXPECT_TRUE(r.ok()) << what << ": " << r.error;
        EXPECT_EQ(validateCloth(w.cloth, area0, uv0), "") << what;
        EXPECT_EQ(w.tearLog.counts[int(TearMode::Knife)] - eventsBefore, r.springsCut) << what;
        EXPECT_EQ(joinedAcross(w, segment), "") << what << ", segment " << i;
        sum.springsCut += r.springsCut, sum.springsSplit += r.springsSplit, sum.particlesAdded += r.particlesAdded;
    }
    EXPECT_EQ(w.tearLog.total(), w.tearLog.counts[int(TearMode::Knife)]) << what << ": a cut is not a tear of the physics";
    return sum;
}

} // namespace

// A straight cut across the whole cloth at 30% of its width: two pieces with 30% and 70% of the area
// (within one triangle's area: crossings near a particle go through it), the same total.
TEST(Knife, StraightCutAcrossMakesTwoPiecesSplitAsTheLine) {
    for (const char* mesh : kMeshes) {
        World w = sheet(mesh);
        const double area0 = w.cloth.totalRestArea(), uv0 = w.cloth.totalUvArea(), tri = meanTriangleArea(w.cloth);
        const MeshFrame& f = w.restFrame;
        ASSERT_NEAR(f.width(), kWidth, 1e-6) << mesh;
        const double u = f.minU + 0.3 * f.width();
        const CutResult r = cutChecked(w, {Vec2d(u, f.maxV + 0.2), Vec2d(u, f.minV - 0.2)}, area0, uv0, mesh);
        EXPECT_GE(r.springsCut, 19u) << mesh << ": at least one edge per row";
        const std::vector<Piece> pieces = findPieces(w.cloth);
        ASSERT_EQ(pieces.size(), 2u) << mesh;
        EXPECT_NEAR(pieces[0].restArea + pieces[1].restArea, area0, 1e-9 * area0) << mesh;
        EXPECT_NEAR(pieces[1].restArea, 0.3 * area0, tri) << mesh;
        EXPECT_NEAR(pieces[0].restArea, 0.7 * area0, tri) << mesh;
        EXPECT_EQ(w.tearLog.knifeCuts, 1u) << mesh;
        // Every event is on the cut (a crossing near a particle moves it by at most a tenth of an edge).
        for (const TearEvent& e : w.tearLog.events) {
            EXPECT_EQ(e.mode, TearMode::Knife);
            EXPECT_NEAR(f.u(e.restPos), u, 0.25 * kSpacing) << mesh;
        }
    }
}

// A cut that ends inside: still one piece, a slit whose two walls are as long as the stroke (new
// boundary = 2 x its length, within a spacing), its ends weak points (tear tips); the stroke of two
// segments cut in one call as cut segment by segment.
TEST(Knife, CutEndingInsideLeavesOnePieceAndASlitOfTheStrokesLength) {
    for (const char* mesh : kMeshes) {
        World w = sheet(mesh);
        const double area0 = w.cloth.totalRestArea(), uv0 = w.cloth.totalUvArea(), border0 = boundaryLength(w.cloth);
        const std::vector<Vec2d> stroke = {Vec2d(-0.31, 0.12), Vec2d(0.04, -0.03), Vec2d(0.22, 0.13)};
        const double length = (stroke[1] - stroke[0]).norm() + (stroke[2] - stroke[1]).norm();
        const CutResult r = cutChecked(w, stroke, area0, uv0, mesh);
        EXPECT_GT(r.springsCut, 0u);
        EXPECT_EQ(findPieces(w.cloth).size(), 1u) << mesh;
        EXPECT_NEAR(boundaryLength(w.cloth) - border0, 2.0 * length, kSpacing) << mesh;
        // The whole polyline in one call cuts the same as its segments one by one (cutChecked): a
        // drawn stroke of several segments is cut along all of them.
        World whole = sheet(mesh);
        const CutResult all = whole.cut(stroke);
        EXPECT_TRUE(all.ok()) << mesh << ": " << all.error;
        EXPECT_EQ(all.springsCut, r.springsCut) << mesh;
        EXPECT_EQ(whole.cloth.particleCount(), w.cloth.particleCount()) << mesh;
        EXPECT_EQ(whole.cloth.rest, w.cloth.rest) << mesh;
        EXPECT_NEAR(boundaryLength(whole.cloth), boundaryLength(w.cloth), 1e-12) << mesh;
        for (const Vec2d& end : {stroke.front(), stroke.back()}) {
            bool tip = false;
            for (Index p = 0; p < w.cloth.particleCount(); ++p)
                tip |= (w.cloth.flags[p] & kWeak) &&
                       (Vec2d(w.restFrame.u(w.cloth.rest[p]), w.restFrame.v(w.cloth.rest[p])) - end).norm() < 0.5 * kSpacing;
            EXPECT_TRUE(tip) << mesh << ": no weak point at the end " << end.transpose();
        }
    }
}

// Exactly along a grid line: only edges are opened (nothing split), the two parts are exactly the
// rows above and below. Exactly through particles (every other row; mid-edge between): two pieces
// with the area left of the line, exactly (no crossing there needs snapping).
TEST(Knife, CutsAlongAGridLineAndThroughParticlesSeparate) {
    {
        World w = sheet("grid");
        const double area0 = w.cloth.totalRestArea(), uv0 = w.cloth.totalUvArea();
        const MeshFrame& f = w.restFrame;
        const double v = f.v(w.cloth.rest[particleNear(w, f.minU, f.maxV - 6 * f.height() / 18)]); // seventh row
        const CutResult r = cutChecked(w, {Vec2d(f.minU - 0.1, v), Vec2d(f.maxU + 0.1, v)}, area0, uv0, "grid line");
        EXPECT_EQ(r.springsSplit, 0u) << "along existing edges nothing needs splitting";
        EXPECT_EQ(r.springsCut, 24u) << "the 24 edges of the row";
        const std::vector<Piece> pieces = findPieces(w.cloth);
        ASSERT_EQ(pieces.size(), 2u);
        EXPECT_NEAR(pieces[1].restArea, (f.maxV - v) * f.width(), 1e-9);
        EXPECT_EQ(pieces[1].triangles, size_t(2 * 24 * 6));
    }
    {
        World w = sheet("grid");
        const double area0 = w.cloth.totalRestArea(), uv0 = w.cloth.totalUvArea();
        const MeshFrame& f = w.restFrame;
        // Through the particle in column 6 of the top row, one column right every two rows down.
        const double dx = f.width() / 24, dy = f.height() / 18;
        const Vec2d top(f.u(w.cloth.rest[particleNear(w, f.minU + 6 * dx, f.maxV)]), f.maxV), dir(0.5 * dx, -dy);
        const Vec2d from = top - 2.0 * dir, to = top + 22.0 * dir;
        const CutResult r = cutChecked(w, {from, to}, area0, uv0, "through particles");
        EXPECT_GT(r.springsCut, 0u);
        const std::vector<Piece> pieces = findPieces(w.cloth);
        ASSERT_EQ(pieces.size(), 2u);
        // Left of u(v) = top.u + (maxV - v) dx / 2dy over the height: a trapezoid (dx and dy differ in
        // the last float bits: the sizes are floats).
        const double left = f.height() * (top.x() - f.minU) + 0.5 * dx / dy * 0.5 * f.height() * f.height();
        EXPECT_NEAR(pieces[1].restArea, left, 1e-9);
        // The particles on the line were split along it: two particles at each of those rest points.
        for (int row = 2; row < 19; row += 2) {
            const Vec3d on = w.cloth.rest[particleNear(w, top.x() + row / 2 * dx, f.maxV - row * dy)];
            int copies = 0;
            for (const Vec3d& r3 : w.cloth.rest) copies += (r3 - on).norm() < 1e-12;
            EXPECT_EQ(copies, 2) << "row " << row;
        }
    }
}

// Cuts through torn cloth: a slit, then a cut across it and another across that: four quadrants
// with their areas. The same stroke again opens nothing; strokes off the cloth change nothing.
TEST(Knife, CutsThroughTornClothAndStrokesThatMissChangeNothing) {
    for (const char* mesh : kMeshes) {
        World w = sheet(mesh);
        const double area0 = w.cloth.totalRestArea(), uv0 = w.cloth.totalUvArea(), tri = meanTriangleArea(w.cloth);
        const MeshFrame& f = w.restFrame;
        cutChecked(w, {Vec2d(-0.2, -0.3), Vec2d(-0.2, 0.25)}, area0, uv0, "slit");
        const double v = f.minV + 0.6 * f.height(), u = f.minU + 0.45 * f.width();
        cutChecked(w, {Vec2d(f.minU - 0.1, v), Vec2d(f.maxU + 0.1, v)}, area0, uv0, "across the slit");
        EXPECT_EQ(findPieces(w.cloth).size(), 2u) << mesh;
        cutChecked(w, {Vec2d(u, f.maxV + 0.1), Vec2d(u, f.minV - 0.1)}, area0, uv0, "across the cut");
        std::vector<Piece> pieces = findPieces(w.cloth);
        ASSERT_EQ(pieces.size(), 4u) << mesh;
        const double expected[4] = {0.55 * 0.6, 0.45 * 0.6, 0.55 * 0.4, 0.45 * 0.4}; // largest first
        for (int k = 0; k < 4; ++k) EXPECT_NEAR(pieces[size_t(k)].restArea, expected[k] * area0, 2 * tri) << mesh << " " << k;

        const size_t particles = w.cloth.particleCount(), springs = w.cloth.springs.size();
        const uint64_t revision = w.cloth.topologyRevision;
        const CutResult again = cutChecked(w, {Vec2d(u, f.maxV + 0.1), Vec2d(u, f.minV - 0.1)}, area0, uv0, "again");
        EXPECT_EQ(again.springsCut, 0u) << mesh << ": already open";
        EXPECT_EQ(again.springsSplit, 0u) << mesh;
        for (const std::vector<Vec2d>& miss : {std::vector<Vec2d>{Vec2d(2, 2), Vec2d(3, 2.5)},
                                               std::vector<Vec2d>{Vec2d(-2, 0.6), Vec2d(2, 0.6), Vec2d(2, 1)}}) {
            const CutResult r = cutChecked(w, miss, area0, uv0, "miss");
            EXPECT_EQ(r.springsCut, 0u);
            EXPECT_EQ(r.particlesAdded, 0u);
        }
        EXPECT_EQ(w.cloth.particleCount(), particles) << mesh;
        EXPECT_EQ(w.cloth.springs.size(), springs) << mesh;
        EXPECT_EQ(w.cloth.topologyRevision, revision) << mesh;
        EXPECT_EQ(w.tearLog.knifeCuts, 3u) << mesh;
    }
}

TEST(Knife, DegenerateStrokesAreRefusedAndChangeNothing) {
    World w = sheet("grid");
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    const struct {
        std::vector<Vec2d> stroke;
        const char* message;
    } cases[] = {
        {{}, "at least two points (got 0)"},
        {{Vec2d(0, 0)}, "at least two points (got 1)"},
        {{Vec2d(0.1, 0.1), Vec2d(0.1, 0.1), Vec2d(0.1, 0.1)}, "no length"},
        {{Vec2d(0, 0), Vec2d(nan, 0.2)}, "point 2 of the cut is not a finite number"},
        {{Vec2d(-inf, 0), Vec2d(0, 0.2)}, "point 1 of the cut is not a finite number"},
        {{Vec2d(0, 0), Vec2d(3e5, 0)}, "point 2 of the cut is beyond +-1e5 m"},
    };
    const size_t particles = w.cloth.particleCount();
    const uint64_t revision = w.cloth.topologyRevision;
    for (const auto& c : cases) {
        const CutResult r = w.cut(c.stroke);
        EXPECT_NE(r.error.find(c.message), std::string::npos) << r.error;
        EXPECT_EQ(checkStroke(c.stroke), r.error);
        EXPECT_EQ(r.springsCut + r.springsSplit + r.particlesAdded, 0u);
    }
    EXPECT_EQ(w.cloth.particleCount(), particles);
    EXPECT_EQ(w.cloth.topologyRevision, revision);
    EXPECT_EQ(w.tearLog.knifeCuts, 0u);
}

// Random strokes of 2 to 4 points over and beyond the cloth, through what earlier strokes cut.
std::vector<Vec2d> randomStroke(Rng& rng) {
    std::vector<Vec2d> stroke(2 + rng.below(3));
    for (Vec2d& p : stroke) p = Vec2d(rng.uniform(-0.75, 0.75), rng.uniform(-0.55, 0.55));
    return stroke;
}

// Many random strokes, every invariant after each segment; mass and area never change.
TEST(Knife, RandomStrokesKeepEveryInvariant) {
    for (const char* mesh : kMeshes) {
        World w = sheet(mesh);
        const double area0 = w.cloth.totalRestArea(), uv0 = w.cloth.totalUvArea(), mass0 = w.cloth.totalMass();
        Rng rng(0x6b6e6966u + uint64_t(mesh[0]));
        size_t cut = 0;
        for (int i = 0; i < 40; ++i) {
            cut += cutChecked(w, randomStroke(rng), area0, uv0, std::string(mesh) + " stroke " + std::to_string(i)).springsCut;
            if (::testing::Test::HasFailure()) return;
        }
        EXPECT_GT(cut, 200u) << mesh;
        EXPECT_NEAR(w.cloth.totalMass(), mass0, 1e-9 * mass0) << mesh;
        double pieces = 0;
        for (const Piece& p : findPieces(w.cloth)) pieces += p.restArea;
        EXPECT_NEAR(pieces, area0, 1e-9 * area0) << mesh;
    }
}

// A randomly cut cloth (its pieces falling, torn further by the physics, validated after every
// tear) simulates finite frames. Few strokes: the cloth stays under the step's threading size.
TEST(Knife, RandomlyCutClothSimulatesFiniteFrames) {
    for (const char* mesh : kMeshes) {
        World w = sheet(mesh);
        const double area0 = w.cloth.totalRestArea(), uv0 = w.cloth.totalUvArea();
        Rng rng(0x73696d75u + uint64_t(mesh[0]));
        for (int i = 0; i < 6; ++i) cutChecked(w, randomStroke(rng), area0, uv0, mesh);
        EXPECT_GT(findPieces(w.cloth).size(), 1u) << mesh;
        w.settings.tear.validate = true;
        for (int f = 0; f < 30; ++f) w.step();
        EXPECT_TRUE(w.finite) << mesh << ": " << w.nonFiniteWhere;
        EXPECT_EQ(w.tearLog.validationError, "") << mesh;
        EXPECT_EQ(validateCloth(w.cloth, area0, uv0), "") << mesh;
    }
}

// The curtain cut from top to bottom hangs as two halves that swing apart: finite, and no particle
// of one half is where the other half's material is.
TEST(Knife, TheCutCurtainSimulatesOnAsTwoHalves) {
    World w = sheet("grid");
    const double area0 = w.cloth.totalRestArea(), uv0 = w.cloth.totalUvArea();
    const MeshFrame& f = w.restFrame;
    cutChecked(w, {Vec2d(0.013, f.maxV + 0.1), Vec2d(-0.021, f.minV - 0.1)}, area0, uv0, "curtain");
    ASSERT_EQ(findPieces(w.cloth).size(), 2u);
    w.settings.tear.validate = true;
    w.balls.push_back(Ball{Vec3(0.f, -0.2f, -0.6f), Vec3(0.f, 0.f, 3.f), 0.15f, 2.f}); // pushes the middle
    for (int frame = 0; frame < 120; ++frame) w.step();
    EXPECT_TRUE(w.finite) << w.nonFiniteWhere;
    EXPECT_EQ(w.tearLog.validationError, "");
    EXPECT_EQ(validateCloth(w.cloth, area0, uv0), "");
}

// A cut is part of the state a checkpoint keeps (history.h): restoring the one taken before the
// cut gives back the uncut cloth exactly, and the one after it the cut cloth.
TEST(Knife, CheckpointsTakeACutBackAndForth) {
    World w = sheet("irregular");
    const uint64_t before = stateHash(w);
    const Checkpoint uncut = Checkpoint::take(w);
    ASSERT_GT(w.cut({Vec2d(0.1, 0.6), Vec2d(-0.1, -0.6)}).springsCut, 0u);
    const uint64_t after = stateHash(w);
    const Checkpoint cut = Checkpoint::take(w, &uncut);
    uncut.restore(w);
    EXPECT_EQ(stateHash(w), before);
    EXPECT_EQ(findPieces(w.cloth).size(), 1u);
    EXPECT_EQ(w.tearLog.knifeCuts, 0u);
    cut.restore(w);
    EXPECT_EQ(stateHash(w), after);
    EXPECT_EQ(findPieces(w.cloth).size(), 2u);
    EXPECT_EQ(w.tearLog.knifeCuts, 1u);
    EXPECT_EQ(cut.tears(), w.tearLog.total());
}
