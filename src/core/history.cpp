// Checkpoints of a World in shared chunks, and the history that keeps them (include/clothtear/history.h).
//
// What a checkpoint holds is listed once, in visitState: taking and restoring walk the same list,
// so a field added there is both kept and put back. Arrays go into chunked sections (shared with the
// previous checkpoint where equal); everything else is copied by value.
#include "clothtear/history.h"

#include "step/implicit_euler.h"
#include "step/step_state.h"

#include <algorithm>
#include <cassert>
#include <cstring>
#include <type_traits>

namespace clothtear {

namespace {

using Chunk = std::shared_ptr<const std::vector<std::byte>>;

// One array of the state: its length in bytes and its chunks.
struct Section {
    size_t bytes = 0;
    std::vector<Chunk> chunks;
};

// Arrays are copied as raw bytes: plain structs and Eigen's fixed-size vectors (no pointers inside).
template <class T>
constexpr bool kRawArray = std::is_standard_layout_v<T> && !std::is_pointer_v<T>;

} // namespace

struct CheckpointData {
    std::vector<Section> sections;     // in visitState's order
    std::vector<std::byte> values;     // plain values, in visitState's order
    std::vector<std::string> strings;  // in visitState's order
    std::vector<Driver> drivers;
    // What the history and the timeline read of a checkpoint without restoring it.
    double time = 0;
    uint64_t steps = 0, tears = 0;
    // The cloth's revisions when taken: the key of its topology sections (Taker::keyed).
    uint64_t topologyRevision = 0, massRevision = 0;
};

namespace {

// Everything a checkpoint keeps, for a const World (taking) or a World (restoring). `Carry` is the
// step state's part that outlives a sub-step: Verlet's half kicks and the sleep state.
template <class W, class S, class F>
void visitState(W& w, S& carry, F& f) {
    auto& c = w.cloth;
    f.array(c.x);
    f.array(c.v);
    f.array(c.invMass);
    f.array(c.areaShare);
    f.array(c.rest);
    f.array(c.flags);
    f.keyedNested(c.particleTris);
    f.keyed(c.springs);
    f.keyed(c.springTopo);
    f.keyed(c.bends);
    f.keyed(c.bendEdge);
    f.array(c.bendMemory);
    f.keyed(c.triangles);
    f.value(c.topologyRevision);
    f.value(c.massRevision);
    f.value(c.density);
    f.value(c.minSplitRest);
    f.value(w.settings);
    f.array(w.balls);
    f.drivers(w.drivers);
    f.value(w.profile);
    f.array(w.tearLog.events);
    f.value(w.tearLog.counts);
    f.value(w.tearLog.knifeCuts);
    f.value(w.tearLog.maxEvents);
    f.string(w.tearLog.validationError);
    f.value(w.time);
    f.value(w.steps);
    f.value(w.maxStrain);
    f.value(w.frameSubsteps);
    f.value(w.guardCappedSprings);
    f.value(w.guardStiffnessKept);
    f.value(w.guardDampingKept);
    f.value(w.maxSpeed);
    f.value(w.asleep);
    f.value(w.sleptFrames);
    f.value(w.finite);
    f.string(w.nonFiniteWhere);
    f.keyed(w.restMesh.positions);
    f.keyed(w.restMesh.triangles);
    f.keyed(w.restMesh.cornerUVs);
    f.value(w.restFrame);
    f.value(carry.verletRunning);
    f.array(carry.verletKick);
    f.value(carry.sleep.restSince);
    f.value(carry.sleep.settings);
    f.value(carry.sleep.topology);
    f.value(carry.sleep.mass);
    f.value(carry.sleep.lo);
    f.value(carry.sleep.hi);
    f.array(carry.sleep.frameStart);
    f.array(carry.sleep.stillFrames);
    f.value(carry.sleep.pieceSettings);
    f.warmStart(carry.implicit, w.cloth);
}

// Implicit Euler's last solve, the next solve's first guess (a world file keeps it too): kept when
// it belongs to this cloth; restored with a stamp saying so (the matrix is rebuilt, the guess kept).
bool warmFor(const ImplicitCacheSlot& slot, const Cloth& cloth) {
    return slot.cache && slot.stamp.valid && slot.stamp.built.topology == cloth.topologyRevision &&
           slot.stamp.built.mass == cloth.massRevision;
}

// Taking: arrays into chunks, each shared with the previous checkpoint's chunk in the same place
// when the bytes are equal.
//
// The topology's arrays (particleTris, springs, springTopo, bends, bendEdge, triangles) and the
// mesh the cloth was built from are most of a checkpoint's bytes (5 of 9 MB at 128 x 128), and
// comparing them every frame was most of its cost. They change only where the cloth gets a new
// mass revision, a process-wide unique number (Cloth::massRevision): a tear (refreshAround), a
// deleted piece, a cloth built or loaded; a restore puts back the arrays with the revision they
// had. So when the previous checkpoint's topology and mass revisions are the cloth's, those
// sections are the previous checkpoint's, shared without a look (`keyed`). Checked byte for byte
// where asserts are on (the sanitizer build), and by History.* restoring torn, cut, re-pinned and
// rewound worlds.
struct Taker {
    CheckpointData& out;
    const CheckpointData* previous;
    bool sameTopology = false; // the previous checkpoint's revisions are the cloth's

    // Section `index` of the previous checkpoint when it can stand for `n` bytes of the same
    // topology (else null).
    const Section* keyedSection(size_t index, size_t n) const {
        if (!sameTopology || index >= previous->sections.size()) return nullptr;
        const Section& s = previous->sections[index];
        return s.bytes == n ? &s : nullptr;
    }
    template <class T>
    void keyed(const std::vector<T>& v) {
        static_assert(kRawArray<T>);
        const size_t n = v.size() * sizeof(T);
        const Section* same = keyedSection(out.sections.size(), n);
        if (!same) return bytes(v.data(), n);
#ifndef NDEBUG
        const auto* src = reinterpret_cast<const std::byte*>(v.data());
        for (size_t k = 0; k < same->chunks.size(); ++k)
            assert(std::memcmp(same->chunks[k]->data(), src + k * kHistoryChunkBytes, same->chunks[k]->size()) == 0 &&
                   "a topology array changed without a new mass revision (Taker::keyed)");
#endif
        out.sections.push_back(*same);
    }
    void keyedNested(const std::vector<std::vector<Index>>& lists) {
        // The lengths' section has one entry a list; the items' follows it.
        const size_t index = out.sections.size();
        if (!keyedSection(index, lists.size() * sizeof(uint32_t)) || index + 1 >= previous->sections.size())
            return nested(lists);
#ifndef NDEBUG
        CheckpointData check;
        Taker{check, nullptr}.nested(lists);
        for (size_t s = 0; s < 2; ++s) {
            const Section& was = previous->sections[index + s];
            assert(was.bytes == check.sections[s].bytes &&
                   "a cloth's particleTris changed without a new mass revision");
            for (size_t k = 0; k < was.chunks.size(); ++k)
                assert(*was.chunks[k] == *check.sections[s].chunks[k] &&
                       "a cloth's particleTris changed without a new mass revision");
        }
#endif
        out.sections.push_back(previous->sections[index]);
        out.sections.push_back(previous->sections[index + 1]);
    }

    void bytes(const void* data, size_t n) {
        const size_t index = out.sections.size();
        Section& s = out.sections.emplace_back();
        s.bytes = n;
        const Section* before = previous && index < previous->sections.size() ? &previous->sections[index] : nullptr;
        const auto* src = static_cast<const std::byte*>(data);
        for (size_t at = 0, k = 0; at < n; at += kHistoryChunkBytes, ++k) {
            const size_t len = std::min(kHistoryChunkBytes, n - at);
            if (before && k < before->chunks.size()) {
                const Chunk& old = before->chunks[k];
                if (old->size() == len && std::memcmp(old->data(), src + at, len) == 0) {
                    s.chunks.push_back(old);
                    continue;
                }
            }
            s.chunks.push_back(std::make_shared<const std::vector<std::byte>>(src + at, src + at + len));
        }
    }
    template <class T>
    void array(const std::vector<T>& v) {
        static_assert(kRawArray<T>);
        bytes(v.data(), v.size() * sizeof(T));
    }
    // A list of lists as two arrays: the lengths, then the items.
    void nested(const std::vector<std::vector<Index>>& lists) {
        std::vector<uint32_t> lengths(lists.size());
        std::vector<Index> items;
        for (size_t i = 0; i < lists.size(); ++i) {
            lengths[i] = uint32_t(lists[i].size());
            items.insert(items.end(), lists[i].begin(), lists[i].end());
        }
        array(lengths);
        array(items);
    }
    template <class T>
    void value(const T& v) {
        static_assert(kRawArray<T>);
        const auto* p = reinterpret_cast<const std::byte*>(&v);
        out.values.insert(out.values.end(), p, p + sizeof(T));
    }
    void string(const std::string& s) { out.strings.push_back(s); }
    void drivers(const std::vector<Driver>& d) { out.drivers = d; }
    void warmStart(const ImplicitCacheSlot& slot, const Cloth& cloth) {
        const bool warm = warmFor(slot, cloth);
        bytes(warm ? slot.cache->dv.data() : nullptr, warm ? size_t(slot.cache->dv.size()) * sizeof(double) : 0);
    }
};

// Restoring: the same walk, reading back.
struct Restorer {
    const CheckpointData& in;
    size_t section = 0, valueAt = 0, stringAt = 0;

    template <class T>
    void keyed(std::vector<T>& v) {
        array(v);
    }
    void keyedNested(std::vector<std::vector<Index>>& lists) { nested(lists); }
    template <class T>
    void array(std::vector<T>& v) {
        const Section& s = in.sections[section++];
        v.resize(s.bytes / sizeof(T));
        auto* dst = reinterpret_cast<std::byte*>(v.data());
        for (const Chunk& c : s.chunks) dst = std::copy(c->begin(), c->end(), dst);
    }
    void nested(std::vector<std::vector<Index>>& lists) {
        std::vector<uint32_t> lengths;
        std::vector<Index> items;
        array(lengths);
        array(items);
        lists.resize(lengths.size());
        size_t at = 0;
        for (size_t i = 0; i < lengths.size(); ++i) {
            lists[i].assign(items.begin() + at, items.begin() + at + lengths[i]);
            at += lengths[i];
        }
    }
    template <class T>
    void value(T& v) {
        std::memcpy(reinterpret_cast<std::byte*>(&v), in.values.data() + valueAt, sizeof(T));
        valueAt += sizeof(T);
    }
    void string(std::string& s) { s = in.strings[stringAt++]; }
    void drivers(std::vector<Driver>& d) { d = in.drivers; }
    void warmStart(ImplicitCacheSlot& slot, const Cloth& cloth) {
        std::vector<double> dv;
        array(dv);
        if (dv.empty()) return;
        slot.cache = std::make_unique<ImplicitEulerCache>();
        slot.cache->dv = Eigen::Map<const Eigen::VectorXd>(dv.data(), Eigen::Index(dv.size()));
        slot.stamp.valid = true;
        slot.stamp.built.topology = cloth.topologyRevision;
        slot.stamp.built.mass = cloth.massRevision;
    }
};

template <class F>
void forEachChunk(const CheckpointData& d, F&& f) {
    for (size_t s = 0; s < d.sections.size(); ++s)
        for (size_t k = 0; k < d.sections[s].chunks.size(); ++k) f(s, k, d.sections[s].chunks[k]);
}

bool holds(const CheckpointData* d, size_t s, size_t k, const Chunk& c) {
    return d && s < d->sections.size() && k < d->sections[s].chunks.size() && d->sections[s].chunks[k] == c;
}

} // namespace

Checkpoint Checkpoint::take(const World& world, const Checkpoint* previous) {
    auto data = std::make_shared<CheckpointData>();
    data->topologyRevision = world.cloth.topologyRevision;
    data->massRevision = world.cloth.massRevision;
    Taker taker{*data, previous ? previous->data_.get() : nullptr};
    taker.sameTopology = taker.previous && taker.previous->topologyRevision == data->topologyRevision &&
                         taker.previous->massRevision == data->massRevision;
    const StepState& carry = world.stepState();
    visitState(world, carry, taker);
    data->time = world.time;
    data->steps = world.steps;
    data->tears = world.tearLog.total();
    Checkpoint c;
    c.data_ = std::move(data);
    return c;
}

void Checkpoint::restore(World& world) const {
    world.resetStepState();
    Restorer restorer{*data_};
    StepState& carry = world.stepState();
    visitState(world, carry, restorer);
}

double Checkpoint::time() const { return data_->time; }
uint64_t Checkpoint::steps() const { return data_->steps; }
uint64_t Checkpoint::tears() const { return data_->tears; }

size_t Checkpoint::bytesNotIn(const Checkpoint* a, const Checkpoint* b) const {
    if (!data_) return 0;
    const CheckpointData* da = a ? a->data_.get() : nullptr;
    const CheckpointData* db = b ? b->data_.get() : nullptr;
    size_t n = data_->values.size() + sizeof(CheckpointData);
    for (const std::string& s : data_->strings) n += s.size();
    for (const Driver& d : data_->drivers) n += d.particles.size() * sizeof(Index) + sizeof(Driver);
    forEachChunk(*data_, [&](size_t s, size_t k, const Chunk& c) {
        if (!holds(da, s, k, c) && !holds(db, s, k, c)) n += c->size();
    });
    return n;
}

// ---- History ------------------------------------------------------------------------------------

size_t History::record(const World& world) {
    if (!entries_.empty() && world.time < entries_.back().checkpoint.time()) clear();
    const Checkpoint* previous = entries_.empty() ? nullptr : &entries_.back().checkpoint;
    Entry e{Checkpoint::take(world, previous), false};
    bytes_ += e.checkpoint.bytesNotIn(previous, nullptr);
    entries_.push_back(std::move(e));
    enforceLimits();
    return entries_.size() - 1;
}

size_t History::indexAtOrBefore(double t) const {
    size_t best = 0;
    for (size_t i = 0; i < entries_.size(); ++i)
        if (entries_[i].checkpoint.time() <= t) best = i;
    return best;
}

void History::truncateAfter(size_t i) {
    while (entries_.size() > i + 1) drop(entries_.size() - 1);
}

void History::clear() {
    entries_.clear();
    bytes_ = 0;
}

void History::setLimits(const HistoryLimits& limits) {
    limits_ = limits;
    enforceLimits();
}

// Dropping entry i frees the chunks neither neighbour shares (a chunk is shared only with the
// checkpoint before it, so the checkpoints holding one chunk are always consecutive).
void History::drop(size_t i) {
    const Checkpoint* prev = i > 0 ? &entries_[i - 1].checkpoint : nullptr;
    const Checkpoint* next = i + 1 < entries_.size() ? &entries_[i + 1].checkpoint : nullptr;
    bytes_ -= entries_[i].checkpoint.bytesNotIn(prev, next);
    entries_.erase(entries_.begin() + ptrdiff_t(i));
}

// Older than `seconds`: gone (kept undo points too: an undo that far back is not offered). Over the
// byte budget: every other checkpoint older than the dense span goes, oldest first, until under it.
void History::enforceLimits() {
    if (entries_.empty()) return;
    const double newest = entries_.back().checkpoint.time();
    while (entries_.size() > 1 && newest - entries_.front().checkpoint.time() > limits_.seconds) drop(0);
    while (bytes_ > limits_.bytes) {
        bool dropped = false;
        for (size_t i = 1; i + 1 < entries_.size() && bytes_ > limits_.bytes; ++i) {
            if (newest - entries_[i].checkpoint.time() <= limits_.denseSeconds) break;
            if (entries_[i].kept) continue;
            drop(i); // the entry that moved into i is kept this round: every other one goes
            dropped = true;
        }
        if (!dropped) {
            // Nothing thinnable left (all dense or kept): the oldest goes.
            if (entries_.size() <= 1) break;
            drop(0);
        }
    }
}

} // namespace clothtear
