// The history behind rewind and undo (include/clothtear/history.h): a checkpoint restores the exact
// state (stateHash equal) and the restored World steps on bit for bit as the original; chunks are
// shared between checkpoints; the limits thin the history without losing count of its bytes.
#include "clothtear/history.h"
#include "clothtear/pieces.h"
#include "clothtear/tear.h"
#include "clothtear/scenes.h"
#include "clothtear/state_hash.h"

#include <gtest/gtest.h>

using namespace clothtear;

namespace {

World loaded(const std::string& scene, const std::vector<std::string>& sets) {
    World w;
    const std::string err = loadScene(w, scene, sets);
    EXPECT_EQ(err, "") << scene;
    return w;
}

struct Case {
    const char* scene;
    std::vector<std::string> sets;
    int frames;
};

// Scenes that tear (tension, balls, pull), blow (flag), fall asleep (curtain with sleep on), collide
// with the ground (drop) and use each explicit integrator's own state (Verlet's half kicks).
const Case kCases[] = {
    {"tension", {"cloth.resolution_x=20", "cloth.resolution_y=14"}, 90},
    {"ball-r1-v3-high", {"cloth.resolution_x=20", "cloth.resolution_y=20"}, 60},
    {"pull", {"cloth.resolution_x=16", "cloth.resolution_y=16", "pull.angle=60"}, 90},
    {"flag", {"cloth.resolution_x=16", "cloth.resolution_y=12"}, 40},
    {"curtain", {"cloth.resolution_x=12", "cloth.resolution_y=12", "sleep.enabled=1"}, 120},
    {"drop", {"cloth.resolution_x=14", "cloth.resolution_y=14"}, 60},
    {"corners", {"cloth.resolution_x=14", "cloth.resolution_y=14", "time.integrator=verlet"}, 40},
    {"swing", {"cloth.resolution_x=12", "cloth.resolution_y=12", "time.integrator=xpbd"}, 30},
    {"curtain", {"cloth.resolution_x=8", "cloth.resolution_y=8", "time.integrator=implicit-euler", "sleep.enabled=0"}, 20},
};

} // namespace

// Every checkpoint of a run, restored into a fresh World, has the run's hash at that frame, and
// stepped to the run's end has its final hash: nothing that decides the future is left out.
TEST(History, EveryCheckpointRestoresTheStateAndStepsOnBitForBit) {
    for (const Case& c : kCases) {
        World w = loaded(c.scene, c.sets);
        History history;
        std::vector<uint64_t> hashes;
        for (int f = 0; f < c.frames; ++f) {
            history.record(w);
            hashes.push_back(stateHash(w));
            w.step();
        }
        const uint64_t final = stateHash(w);
        ASSERT_EQ(history.size(), size_t(c.frames)) << c.scene;
        if (std::string(c.scene) == "tension" || std::string(c.scene) == "ball-r1-v3-high") {
            EXPECT_GT(w.tearLog.total(), 0u) << c.scene << ": the case is meant to tear";
        }
        for (size_t i : {size_t(0), size_t(c.frames / 3), size_t(c.frames / 2), size_t(c.frames - 1)}) {
            World r = loaded("curtain", {"cloth.resolution_x=5", "cloth.resolution_y=5"}); // any other world
            history.at(i).restore(r);
            EXPECT_EQ(hashHex(stateHash(r)), hashHex(hashes[i])) << c.scene << " checkpoint " << i;
            EXPECT_EQ(history.at(i).steps(), i) << c.scene;
            EXPECT_EQ(r.tearLog.total(), history.at(i).tears()) << c.scene;
            for (int f = int(i); f < c.frames; ++f) r.step();
            EXPECT_EQ(hashHex(stateHash(r)), hashHex(final)) << c.scene << " from checkpoint " << i;
        }
    }
}

// A checkpoint shares the topology's sections with the one before without comparing them when the
// cloth's topology and mass revisions are the same (history.cpp, Taker::keyed): every way the
// topology or the masses change between frames (a knife cut, a pin, a deleted piece, a rewind of
// the running world to an earlier frame and a different cut from there) must still give checkpoints
// that restore each frame exactly. A change the revisions missed would restore the old topology.
TEST(History, CheckpointsOfCutPinnedDeletedAndRewoundWorldsRestoreEachFrame) {
    World w = loaded("curtain", {"cloth.resolution_x=24", "cloth.resolution_y=24", "sleep.enabled=0"});
    History history;
    std::vector<uint64_t> hashes;
    auto frame = [&] {
        hashes.resize(history.size());
        history.record(w);
        hashes.push_back(stateHash(w));
        w.step();
    };
    for (int f = 0; f < 8; ++f) frame();
    ASSERT_GT(w.cut({Vec2d(0.2, 0.9), Vec2d(0.1, -0.2)}).springsCut, 0u); // a slit
    for (int f = 0; f < 5; ++f) frame();
    w.cloth.setPinned(Index(w.cloth.particleCount() / 2), true);
    for (int f = 0; f < 5; ++f) frame();
    ASSERT_GT(w.cut({Vec2d(-1.5, -0.6), Vec2d(1.5, -0.6)}).springsCut, 0u); // the bottom cut off
    std::vector<Piece> pieces = findPieces(w.cloth);
    ASSERT_EQ(pieces.size(), 2u);
    frame();
    ASSERT_GT(w.deletePiece(pieces[1].firstTriangle), 0u);
    for (int f = 0; f < 5; ++f) frame();
    // Back to frame 10 (after the slit, before the pin) in the running world, and another cut.
    const size_t back = 10;
    history.at(back).restore(w);
    history.truncateAfter(back);
    ASSERT_EQ(hashHex(stateHash(w)), hashHex(hashes[back]));
    w.step();
    ASSERT_GT(w.cut({Vec2d(-0.6, 0.9), Vec2d(-0.5, 0.1)}).springsCut, 0u);
    for (int f = 0; f < 6; ++f) frame();
    ASSERT_EQ(history.size(), hashes.size());
    for (size_t i = 0; i < history.size(); ++i) {
        World r = loaded("curtain", {"cloth.resolution_x=5", "cloth.resolution_y=5"});
        history.at(i).restore(r);
        EXPECT_EQ(hashHex(stateHash(r)), hashHex(hashes[i])) << "checkpoint " << i;
        EXPECT_EQ(validateCloth(r.cloth), "") << "checkpoint " << i;
    }
}

// Rewinding the running World itself (caches built for a later, torn cloth) and stepping on gives
// the same frames again, and the history, truncated there, records the same future.
TEST(History, RewindingTheSameWorldReplaysTheSameFrames) {
    World w = loaded("tension", {"cloth.resolution_x=20", "cloth.resolution_y=14"});
    History history;
    std::vector<uint64_t> hashes;
    for (int f = 0; f < 90; ++f) {
        history.record(w);
        hashes.push_back(stateHash(w));
        w.step();
    }
    ASSERT_GT(w.tearLog.total(), 0u);
    const size_t back = 40;
    ASSERT_LT(history.at(back).tears(), w.tearLog.total()) << "the rewind crosses tears";
    history.at(back).restore(w);
    history.truncateAfter(back);
    EXPECT_EQ(history.size(), back + 1);
    for (size_t f = back; f < 90; ++f) {
        EXPECT_EQ(stateHash(w), hashes[f]) << "frame " << f;
        if (f > back) history.record(w);
        w.step();
    }
    EXPECT_EQ(history.size(), size_t(90));
}

// A swinging cloth's frame costs about its positions and velocities (24 bytes a particle, plus
// the sleep state's frame-start copy when sleep is on); the topology is kept once; a tear adds only
// the chunks it rewrote. The history's byte count equals a recount after drops and truncations.
TEST(History, CheckpointsShareWhatDidNotChange) {
    World w = loaded("curtain", {"cloth.resolution_x=48", "cloth.resolution_y=48", "sleep.enabled=0"});
    w.applyImpulse(Vec3(0, 0, 0), 10.f, Vec3(0, 0, 1), 1.f); // swinging: every position moves
    History history;
    history.record(w);
    const size_t first = history.bytes();
    w.step();
    history.record(w);
    const size_t perFrame = history.bytes() - first;
    const size_t n = w.cloth.particleCount(), xv = n * 2 * sizeof(Vec3);
    EXPECT_GE(perFrame, xv) << "positions and velocities changed";
    EXPECT_LT(perFrame, xv + 4 * kHistoryChunkBytes + 4096) << "only they (and chunk rounding)";
    EXPECT_GT(first, 5 * xv) << "the first checkpoint holds the topology";

    // Recount: the bytes of the first checkpoint alone plus what each added after the one before.
    auto recount = [&] {
        size_t total = 0;
        for (size_t i = 0; i < history.size(); ++i) total += history.at(i).bytesNotIn(i ? &history.at(i - 1) : nullptr, nullptr);
        return total;
    };
    for (int f = 0; f < 20; ++f) w.step(), history.record(w);
    EXPECT_EQ(history.bytes(), recount());
    history.truncateAfter(10);
    EXPECT_EQ(history.bytes(), recount());
    HistoryLimits tight;
    tight.denseSeconds = 0.05;
    tight.bytes = first + 4 * perFrame;
    history.setLimits(tight);
    EXPECT_LE(history.bytes(), tight.bytes);
    EXPECT_EQ(history.bytes(), recount());
    EXPECT_GE(history.size(), 3u) << "the newest frames (dense span) stay";
}

// Over the budget, every other old checkpoint goes, but one kept (an undo point) stays, and the
// newest seconds stay whole; beyond `seconds` everything goes.
TEST(History, LimitsThinOldCheckpointsButKeepUndoPointsAndTheNewestSeconds) {
    World w = loaded("curtain", {"cloth.resolution_x=16", "cloth.resolution_y=16", "sleep.enabled=0"});
    w.applyImpulse(Vec3(0, 0, 0), 10.f, Vec3(0, 0, 1), 1.f);
    HistoryLimits limits;
    limits.seconds = 1.0;
    limits.denseSeconds = 0.25;
    History history(limits);
    history.record(w);
    history.keep(0, true);
    w.step();
    history.record(w);
    const size_t perFrame = history.bytes() - history.at(0).bytesNotIn(nullptr, nullptr);
    history.keep(1, true);
    limits.bytes = history.bytes() + 30 * perFrame;
    history.setLimits(limits);
    const double dt = w.settings.time.frameDt;
    for (int f = 0; f < 50; ++f) w.step(), history.record(w);
    EXPECT_LE(history.bytes(), limits.bytes);
    EXPECT_EQ(history.at(0).steps(), 0u) << "the kept checkpoint stays";
    EXPECT_EQ(history.at(1).steps(), 1u);
    // The newest 0.25 s: one checkpoint per frame.
    const size_t last = history.size() - 1;
    const int dense = int(0.25 / dt);
    for (int k = 1; k <= dense; ++k) EXPECT_EQ(history.at(last - k).steps() + k, history.at(last).steps());
    for (int f = 0; f < 60; ++f) w.step(), history.record(w);
    EXPECT_LE(history.at(last).time(), w.time);
    EXPECT_LE(w.time - history.at(0).time(), limits.seconds + 1e-9) << "older than `seconds`: gone, kept or not";
}

// A reset (time back to 0) starts the history afresh.
TEST(History, AResetStartsAfresh) {
    World w = loaded("curtain", {"cloth.resolution_x=8", "cloth.resolution_y=8"});
    History history;
    for (int f = 0; f < 5; ++f) history.record(w), w.step();
    ASSERT_EQ(w.rebuild(), "");
    history.record(w);
    EXPECT_EQ(history.size(), 1u);
    EXPECT_EQ(history.at(0).steps(), 0u);
}
