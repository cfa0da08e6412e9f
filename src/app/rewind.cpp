// Rewind and undo: the timeline of checkpoints and the tear groups (rewind.h).
#include "rewind.h"

#include <limits>

namespace clothtear::app {

void Rewind::restart(const World& world) {
    history_.clear();
    undo_.clear();
    redo_.clear();
    groupOpen_ = gestureHeld_ = gestureLive_ = false;
    lastTears_ = world.tearLog.total();
    viewing_ = -1;
    history_.record(world);
}

void Rewind::afterStep(const World& world) {
    if (viewing_ >= 0) resume(); // stepped on from a frame of the past (N while viewing it)
    const Checkpoint before = history_.size() ? history_.at(history_.size() - 1) : Checkpoint{};
    history_.record(world);
    if (gestureLive_ && !gestureHeld_ && world.time > gestureEndTime_ + kGestureTail) gestureLive_ = false;
    const uint64_t tears = world.tearLog.total();
    if (tears > lastTears_) {
        if (!groupOpen_) {
            Group g{gestureLive_ ? gestureStart_ : before, 0, {}};
            if (g.before.empty()) g.before = history_.at(0); // no frame before this one was recorded
            g.tearsBefore = g.before.tears();
            undo_.push_back(std::move(g));
            if (undo_.size() > kMaxUndo) undo_.erase(undo_.begin());
            groupOpen_ = true;
        }
        redo_.clear();
        lastTearTime_ = world.time;
    } else if (groupOpen_ && !gestureLive_ && world.time - lastTearTime_ > kQuietGap) {
        closeGroup();
    }
    lastTears_ = tears;
}

void Rewind::gestureStarted(const World& world, bool held) {
    if (viewing_ >= 0) resume();
    closeGroup();
    gestureLive_ = true;
    gestureHeld_ = held;
    gestureEndTime_ = held ? std::numeric_limits<double>::infinity() : world.time;
    // The world now, not the newest checkpoint: a pin or a parameter set while paused is part of
    // "before". Shares every unchanged chunk with the newest checkpoint.
    const Checkpoint* newest = history_.size() ? &history_.at(history_.size() - 1) : nullptr;
    gestureStart_ = Checkpoint::take(world, newest);
}

void Rewind::gestureEnded(const World& world) {
    if (!gestureLive_ || !gestureHeld_) return;
    gestureHeld_ = false;
    gestureEndTime_ = world.time;
}

// Restores c and makes it the newest frame of the timeline: frames from c's on are dropped, and the
// tear groups are closed (the next tear starts a new one).
void Rewind::jumpTo(World& world, const Checkpoint& c) {
    c.restore(world);
    size_t keep = 0;
    while (keep < history_.size() && history_.at(keep).steps() < c.steps()) ++keep;
    if (keep == 0) history_.clear();
    else history_.truncateAfter(keep - 1);
    history_.record(world);
    groupOpen_ = gestureHeld_ = gestureLive_ = false;
    lastTears_ = world.tearLog.total();
    viewing_ = -1;
}

void Rewind::beforeEdit(const World& world, const std::string& what) {
    if (viewing_ >= 0) resume();
    closeGroup();
    gestureLive_ = false;
    const Checkpoint* newest = history_.size() ? &history_.at(history_.size() - 1) : nullptr;
    undo_.push_back(Group{Checkpoint::take(world, newest), world.tearLog.total(), what});
    if (undo_.size() > kMaxUndo) undo_.erase(undo_.begin());
    redo_.clear();
}

std::string Rewind::undo(World& world) {
    if (viewing_ >= 0) resume();
    if (undo_.empty()) return {};
    const Group g = undo_.back();
    undo_.pop_back();
    const uint64_t undone = world.tearLog.total() - g.tearsBefore;
    redo_.push_back(Checkpoint::take(world, history_.size() ? &history_.at(history_.size() - 1) : nullptr));
    jumpTo(world, g.before);
    const std::string what = g.what.empty() ? std::to_string(undone) + (undone == 1 ? " tear" : " tears") : g.what;
    return "Undid " + what + " (Ctrl+Shift+Z redoes)";
}

std::string Rewind::redo(World& world) {
    if (viewing_ >= 0) resume();
    if (redo_.empty()) return {};
    const Checkpoint c = redo_.back();
    redo_.pop_back();
    Group back{Checkpoint::take(world, history_.size() ? &history_.at(history_.size() - 1) : nullptr), 0, {}};
    back.tearsBefore = world.tearLog.total();
    undo_.push_back(std::move(back));
    const uint64_t redone = c.tears() - world.tearLog.total();
    std::vector<Checkpoint> rest = std::move(redo_);
    jumpTo(world, c);
    redo_ = std::move(rest); // jumpTo is a jump, not a new tear: what is left to redo stays
    return "Redid " + std::to_string(redone) + (redone == 1 ? " tear" : " tears");
}

void Rewind::view(World& world, size_t index) {
    if (index >= history_.size()) return;
    history_.at(index).restore(world);
    viewing_ = int(index);
    groupOpen_ = gestureHeld_ = gestureLive_ = false;
    lastTears_ = world.tearLog.total();
}

// Going on from the frame shown: the frames after it, and the undo points after it, belong to a
// future that will not happen now.
void Rewind::resume() {
    if (viewing_ < 0) return;
    const uint64_t steps = history_.at(size_t(viewing_)).steps();
    history_.truncateAfter(size_t(viewing_));
    while (!undo_.empty() && undo_.back().before.steps() > steps) undo_.pop_back();
    redo_.clear();
    viewing_ = -1;
}

} // namespace clothtear::app
