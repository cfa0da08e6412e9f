// The recent past of a World, kept in memory: rewind to any recorded frame and go on from there, and
// the restore points behind undoing a tear (issue 14).
//
// A checkpoint is the whole state that decides what the World does next: the cloth (topology, rest
// data, UVs, flags, positions, velocities), balls, drivers, settings, the tear log, time and step
// count, and the step's integrator and sleep state. The step's caches are not kept: a restored World
// starts with empty caches and rebuilds them, as every cache is a function of the state above
// (revisions.h). So a World restored from a checkpoint steps on bit for bit as the World it was taken
// from (same stateHash after any number of frames), and stateHash right after the restore equals the
// hash at the checkpoint.
//
// Memory: each array is kept in chunks of kHistoryChunkBytes, and a chunk equal to the same chunk of
// the checkpoint before it is shared, not copied. A frame of a swinging cloth then costs its
// positions and velocities (24 bytes a particle); a tear adds the few chunks it rewrote; the
// topology is kept once, and while the cloth's topology and mass revisions stay those of the
// checkpoint before, its arrays are shared without comparing them (history.cpp, Taker::keyed: every
// change to them gives the cloth a new mass revision). Checkpoints can be dropped in any order
// (thinning keeps every other one).
#pragma once
#include "clothtear/world.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace clothtear {

inline constexpr size_t kHistoryChunkBytes = 16 * 1024;

struct CheckpointData; // history.cpp

// One recorded state; cheap to copy (shares its chunks and everything else).
class Checkpoint {
public:
    Checkpoint() = default;
    // Takes the state of `world`, sharing every chunk equal to the same chunk of `previous` (a
    // checkpoint of the same World a little earlier; null: nothing shared).
    static Checkpoint take(const World& world, const Checkpoint* previous = nullptr);
    // Puts the state back into `world` (its caches start empty). The World's settings come back
    // too: a rewind also takes back a parameter changed since.
    void restore(World& world) const;

    bool empty() const { return !data_; }
    double time() const;     // s, simulated
    uint64_t steps() const;  // the World's frame count
    uint64_t tears() const;  // tears so far (tearLog.total())
    // Bytes this checkpoint holds that neither `a` nor `b` (its neighbours in a history, or null)
    // shares: what it added when taken after `a`, or what dropping it from between a and b frees.
    size_t bytesNotIn(const Checkpoint* a, const Checkpoint* b) const;

private:
    std::shared_ptr<const CheckpointData> data_;
};

// Checkpoints of consecutive frames, oldest first, within a time span and a memory budget.
struct HistoryLimits {
    double seconds = 20;              // s of simulated time kept behind the newest checkpoint
    size_t bytes = size_t(768) << 20; // when the checkpoints hold more, older ones are thinned
    double denseSeconds = 2;          // the newest seconds are never thinned (every frame kept)
};

class History {
public:
    explicit History(HistoryLimits limits = {}) : limits_(limits) {}

    // Records the world as it is now (call at the start of a frame, before stepping). A world whose
    // time went back (a reset) starts the history afresh. Returns the new checkpoint's index.
    size_t record(const World& world);

    size_t size() const { return entries_.size(); }
    const Checkpoint& at(size_t i) const { return entries_[i].checkpoint; }
    // The newest checkpoint taken at or before simulated time `t` (0 when all are later).
    size_t indexAtOrBefore(double t) const;
    // Drops every checkpoint after i (resuming from i starts a new future).
    void truncateAfter(size_t i);
    void clear();

    // Keeps checkpoint i however the history is thinned (an undo point); unkeep when it no longer is.
    void keep(size_t i, bool on) { entries_[i].kept = on; }

    size_t bytes() const { return bytes_; } // held by all checkpoints together
    const HistoryLimits& limits() const { return limits_; }
    void setLimits(const HistoryLimits& limits);

private:
    struct Entry {
        Checkpoint checkpoint;
        bool kept = false;
    };
    void drop(size_t i);
    void enforceLimits();

    HistoryLimits limits_;
    std::vector<Entry> entries_;
    size_t bytes_ = 0;
};

} // namespace clothtear
