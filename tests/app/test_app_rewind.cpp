// Rewind and undo as the app drives them (src/app/rewind.h), on real Worlds: a thrown ball's holes
// undone give back the state before the throw (stateHash equal), redo gives back the torn state,
// tears with no gesture group by pauses, and the timeline resumes from a frame of the past.
#include "rewind.h"

#include "clothtear/pieces.h"
#include "../curtain_world.h"
#include "clothtear/scenes.h"
#include "clothtear/state_hash.h"
#include "clothtear/tear.h"

#include <gtest/gtest.h>

using namespace clothtear;
using clothtear::test::curtainWorld;
using namespace clothtear::app;

namespace {

// A heavy ball thrown at the curtain's middle: it tears through.
Ball throughTheMiddle() {
    Ball b;
    b.x = Vec3(0, 0, 1.5f);
    b.v = Vec3(0, 0, -12);
    b.radius = 0.25f;
    b.mass = 20;
    return b;
}

} // namespace

TEST(AppRewind, UndoingABallTakesBackTheThrowAndItsHolesExactlyAndRedoGivesThemBack) {
    for (int res : {20, 40}) {
        World w = curtainWorld(res);
        Rewind rewind;
        rewind.restart(w);
        for (int f = 0; f < 10; ++f) w.step(), rewind.afterStep(w);
        const uint64_t before = stateHash(w);
        const size_t particlesBefore = w.cloth.particleCount();
        rewind.gestureStarted(w, false); // the ball tool: the gesture starts before the ball exists
        w.balls.push_back(throughTheMiddle());
        for (int f = 0; f < 40; ++f) w.step(), rewind.afterStep(w);
        ASSERT_GT(w.tearLog.total(), 0u) << res << ": the ball is meant to tear";
        const uint64_t torn = stateHash(w);
        const uint64_t tears = w.tearLog.total();
        EXPECT_TRUE(rewind.canUndo());
        const std::string said = rewind.undo(w);
        EXPECT_EQ(said, "Undid " + std::to_string(tears) + " tears (Ctrl+Shift+Z redoes)");
        EXPECT_EQ(hashHex(stateHash(w)), hashHex(before)) << res << ": the state before the throw";
        EXPECT_EQ(w.cloth.particleCount(), particlesBefore);
        EXPECT_TRUE(w.balls.empty()) << "the throw is taken back too";
        EXPECT_EQ(validateCloth(w.cloth), "");
        EXPECT_FALSE(rewind.canUndo());
        ASSERT_TRUE(rewind.canRedo());
        EXPECT_NE(rewind.redo(w), "");
        EXPECT_EQ(hashHex(stateHash(w)), hashHex(torn)) << res << ": redo gives the torn cloth back";
        EXPECT_TRUE(rewind.canUndo());
        EXPECT_NE(rewind.undo(w), "");
        EXPECT_EQ(hashHex(stateHash(w)), hashHex(before));
        // Stepping on from the undone state is a new future: the same throw tears the same way.
        w.balls.push_back(throughTheMiddle());
        for (int f = 0; f < 40; ++f) w.step(), rewind.afterStep(w);
        EXPECT_EQ(hashHex(stateHash(w)), hashHex(torn)) << "the past replays bit for bit";
        EXPECT_FALSE(rewind.canRedo()) << "a new tear clears redo";
    }
}

// Two gestures, two groups: the second undo goes back before the first throw.
TEST(AppRewind, EachGestureIsItsOwnGroup) {
    World w = curtainWorld(24);
    Rewind rewind;
    rewind.restart(w);
    const uint64_t start = stateHash(w);
    rewind.gestureStarted(w, false);
    Ball b = throughTheMiddle();
    b.x.x() = -0.4f;
    w.balls.push_back(b);
    for (int f = 0; f < 30; ++f) w.step(), rewind.afterStep(w);
    const uint64_t firstTears = w.tearLog.total();
    ASSERT_GT(firstTears, 0u);
    const uint64_t afterFirst = stateHash(w);
    rewind.gestureStarted(w, false);
    b.x.x() = 0.4f;
    w.balls.push_back(b);
    for (int f = 0; f < 30; ++f) w.step(), rewind.afterStep(w);
    ASSERT_GT(w.tearLog.total(), firstTears);
    EXPECT_EQ(rewind.undoCount(), 2u);
    rewind.undo(w);
    EXPECT_EQ(hashHex(stateHash(w)), hashHex(afterFirst));
    rewind.undo(w);
    EXPECT_EQ(hashHex(stateHash(w)), hashHex(start));
    EXPECT_EQ(w.tearLog.total(), 0u);
}

// Tears no gesture made (the tension scene's clamps pull the sheet apart by themselves) group by
// pauses of kQuietGap: the undo point is the frame before the group's first tear.
TEST(AppRewind, TearsWithoutAGestureUndoToTheFrameBeforeTheFirst) {
    World w;
    const std::vector<std::string> sets{"cloth.resolution_x=20", "cloth.resolution_y=14"};
    ASSERT_EQ(loadScene(w, "tension", sets), "");
    Rewind rewind;
    rewind.restart(w);
    std::vector<uint64_t> hashes{stateHash(w)};
    std::vector<uint64_t> tears{0};
    for (int f = 0; f < 90; ++f) {
        w.step(), rewind.afterStep(w);
        hashes.push_back(stateHash(w));
        tears.push_back(w.tearLog.total());
    }
    ASSERT_GT(w.tearLog.total(), 0u);
    size_t first = 0;
    while (tears[first] == 0) ++first; // after frame `first` the first tears are there
    bool quiet = false; // a second without a tear after the first would start a second group
    for (size_t f = first, last = first; f < tears.size(); ++f) {
        if (tears[f] > tears[f - 1]) last = f;
        if ((f - last) * w.settings.time.frameDt > Rewind::kQuietGap) quiet = true;
    }
    ASSERT_FALSE(quiet) << "one group expected in this run";
    ASSERT_EQ(rewind.undoCount(), 1u);
    EXPECT_EQ(rewind.undo(w), "Undid " + std::to_string(tears.back()) + " tears (Ctrl+Shift+Z redoes)");
    EXPECT_EQ(hashHex(stateHash(w)), hashHex(hashes[first - 1])) << "the frame before the first tear";
    EXPECT_EQ(w.tearLog.total(), 0u);
}

// The timeline: view a frame of the past, step on from it: the frames after it are dropped and the
// world goes on as it did (no gesture in between, so the same future).
TEST(AppRewind, TheTimelineResumesFromAFrameOfThePast) {
    World w = curtainWorld(20);
    w.applyImpulse(Vec3(0, 0, 0), 10.f, Vec3(0, 0, 1), 2.f);
    Rewind rewind;
    rewind.restart(w);
    std::vector<uint64_t> hashes{stateHash(w)};
    for (int f = 0; f < 30; ++f) w.step(), rewind.afterStep(w), hashes.push_back(stateHash(w));
    ASSERT_EQ(rewind.history().size(), 31u);
    rewind.view(w, 12);
    EXPECT_EQ(rewind.viewing(), 12);
    EXPECT_EQ(hashHex(stateHash(w)), hashHex(hashes[12]));
    rewind.view(w, 25); // scrubbing forward again: the future is still there while viewing
    EXPECT_EQ(hashHex(stateHash(w)), hashHex(hashes[25]));
    rewind.view(w, 12);
    w.step();
    rewind.afterStep(w);
    EXPECT_EQ(rewind.viewing(), -1);
    EXPECT_EQ(rewind.history().size(), 14u) << "frames 0..12, then the new 13";
    EXPECT_EQ(hashHex(stateHash(w)), hashHex(hashes[13]));
}

TEST(AppRewind, NothingToUndoOrRedoSaysNothingAndChangesNothing) {
    World w = curtainWorld(10);
    Rewind rewind;
    rewind.restart(w);
    for (int f = 0; f < 5; ++f) w.step(), rewind.afterStep(w);
    const uint64_t h = stateHash(w);
    EXPECT_EQ(rewind.undo(w), "");
    EXPECT_EQ(rewind.redo(w), "");
    EXPECT_EQ(stateHash(w), h);
}

// A piece deleted from the stats pane (World::deletePiece) comes back whole with Ctrl+Z, as the
// app does it: beforeEdit, then the deletion. The piece is the curtain's lower part, cut off with
// the knife across its whole width (a ball's hole need not let a piece go).
TEST(AppRewind, ADeletedPieceComesBackWithUndo) {
    World w = curtainWorld(24);
    Rewind rewind;
    rewind.restart(w);
    rewind.beforeEdit(w, "a cut");
    ASSERT_GT(w.cut({Vec2d(-1.2, -0.4), Vec2d(1.2, -0.4)}).springsCut, 0u);
    for (int f = 0; f < 30; ++f) w.step(), rewind.afterStep(w);
    std::vector<Piece> pieces = findPieces(w.cloth);
    ASSERT_GE(pieces.size(), 2u) << "the knife is meant to cut the lower part off";
    const uint64_t before = stateHash(w);
    const size_t particles = w.cloth.particleCount();
    rewind.beforeEdit(w, "the deletion of a piece");
    EXPECT_EQ(w.deletePiece(pieces[1].firstTriangle), pieces[1].triangles);
    EXPECT_EQ(findPieces(w.cloth).size(), pieces.size() - 1);
    for (int f = 0; f < 5; ++f) w.step(), rewind.afterStep(w);
    EXPECT_EQ(rewind.undo(w), "Undid the deletion of a piece (Ctrl+Shift+Z redoes)");
    EXPECT_EQ(hashHex(stateHash(w)), hashHex(before));
    EXPECT_EQ(w.cloth.particleCount(), particles);
    EXPECT_EQ(findPieces(w.cloth).size(), pieces.size());
}
