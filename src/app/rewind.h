// Rewind and undo in the app (issue 14): the recent past as a timeline of checkpoints, and tears
// grouped by what made them, each group undoable ("sew back") and redoable. No GL: tested in
// tests/app with real Worlds.
//
// The app records a checkpoint after every simulated frame (and one when a scene loads), so the
// newest checkpoint is always the state a user's next action starts from.
//
// Tear groups. A gesture (a drag, a knife stroke, a thrown ball, an impulse, a gust of the wind tool)
// opens a group when it starts; its undo point is the newest checkpoint then, the state before the
// gesture. Tears while the gesture is held, or within kGestureTail seconds after it ended, belong to
// its group, so undoing a thrown ball takes back the throw and the holes it made. Tears with no
// gesture about (gravity, the wind setting) form a group that ends after kQuietGap seconds without
// a tear; its undo point is the frame before its first tear. Undo restores the undo point exactly
// (stateHash equal to the state before); redo restores the state undo left. A new tear clears redo.
#pragma once
#include "clothtear/history.h"

#include <string>
#include <vector>

namespace clothtear::app {

class Rewind {
public:
    static constexpr double kGestureTail = 1.5; // s simulated after a gesture ends that its tears still count
    static constexpr double kQuietGap = 1.0;    // s without a tear that ends a group no gesture made
    static constexpr size_t kMaxUndo = 64;      // groups kept for undo (oldest dropped first)

    explicit Rewind(HistoryLimits limits = {}) : history_(limits) {}

    // After a scene load or a reset: the past of the old cloth is gone.
    void restart(const World& world);
    // After each simulated frame: records it and sorts its tears into groups.
    void afterStep(const World& world);
    // A gesture starts (held: until gestureEnded; not held: a throw or an impulse, over at once).
    void gestureStarted(const World& world, bool held);
    void gestureEnded(const World& world);

    // An edit that is not a tear but is undone like one (a piece deleted): call before it, with
    // what it is ("the deletion of a piece") for the undo's message.
    void beforeEdit(const World& world, const std::string& what);

    bool canUndo() const { return !undo_.empty(); }
    bool canRedo() const { return !redo_.empty(); }
    // Restore the state before the last group of tears / the state the last undo left. Return a
    // line for the status bar ("" when there was nothing to do).
    std::string undo(World& world);
    std::string redo(World& world);

    // The timeline. Viewing shows a recorded frame (the app pauses); resuming from it drops the
    // frames after it. viewing() is the index shown, or -1 when the World is live.
    const History& history() const { return history_; }
    void view(World& world, size_t index);
    int viewing() const { return viewing_; }
    void resume(); // the app steps on from the frame shown: its future is recorded anew
    void setLimits(const HistoryLimits& limits) { history_.setLimits(limits); }

    size_t undoCount() const { return undo_.size(); }
    size_t redoCount() const { return redo_.size(); }

private:
    struct Group {
        Checkpoint before;  // the undo point
        uint64_t tearsBefore = 0;
        std::string what;   // an edit's name; empty: a group of tears
    };
    void closeGroup() { groupOpen_ = false; }
    void jumpTo(World& world, const Checkpoint& c);

    History history_;
    std::vector<Group> undo_;
    std::vector<Checkpoint> redo_;
    // The open group and the gesture it may belong to.
    bool groupOpen_ = false;
    double lastTearTime_ = -1e30;
    uint64_t lastTears_ = 0;
    bool gestureHeld_ = false;
    bool gestureLive_ = false;        // a gesture started and its tail has not run out
    double gestureEndTime_ = -1e30;  // s simulated; while held: +inf
    Checkpoint gestureStart_;        // the state before the live gesture
    int viewing_ = -1;
};

} // namespace clothtear::app
