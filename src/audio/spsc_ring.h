// A lock-free ring buffer for one producer thread and one consumer thread (single-producer,
// single-consumer): the app's simulation pushes the rip synthesizer's samples, the audio device's
// callback pops them (src/app/audio_out.cpp). Neither side ever waits or locks: push() takes what
// fits and says how much, pop() takes what is there and says how much.
//
//   head_ (written by the producer only)        tail_ (written by the consumer only)
//   counts every element ever pushed            counts every element ever popped
//
//        tail_ % N             head_ % N
//   [ . . | x x x x x x x x x x | . . . . ]      size = head_ - tail_, free = N - size
//            popped next           pushed next
//
// Both counters only grow (64 bits: centuries at 96 kHz); the slot of count c is c & (N - 1). The
// producer publishes its elements with a release store of head_ after writing them, the consumer
// reads head_ with acquire before reading them (and the other way round for tail_), so an element is
// never read before it is written nor overwritten before it is read.
#pragma once
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <type_traits>

namespace clothtear::audio {

template <class T>
class SpscRing {
    static_assert(std::is_trivially_copyable_v<T>, "elements are copied as plain values");

public:
    // capacity: the most elements held at once, rounded up to a power of two (at least 2).
    explicit SpscRing(size_t capacity) {
        size_t n = 2;
        while (n < capacity) n *= 2;
        mask_ = n - 1;
        slots_ = std::make_unique<T[]>(n);
    }
    SpscRing(const SpscRing&) = delete;
    SpscRing& operator=(const SpscRing&) = delete;

    size_t capacity() const { return mask_ + 1; }

    // Producer: copies up to n elements in, as many as fit; returns how many.
    size_t push(const T* data, size_t n) {
        const uint64_t head = head_.load(std::memory_order_relaxed); // ours
        const uint64_t tail = tail_.load(std::memory_order_acquire); // the consumer's
        const size_t count = std::min(n, capacity() - size_t(head - tail));
        copyIn(head, data, count);
        head_.store(head + count, std::memory_order_release);
        return count;
    }

    // Consumer: copies up to n elements out, as many as there are; returns how many.
    size_t pop(T* out, size_t n) {
        const uint64_t tail = tail_.load(std::memory_order_relaxed); // ours
        const uint64_t head = head_.load(std::memory_order_acquire); // the producer's
        const size_t count = std::min(n, size_t(head - tail));
        copyOut(tail, out, count);
        tail_.store(tail + count, std::memory_order_release);
        return count;
    }

    // Elements held now. Exact from either side's own point of view (the other side may have moved
    // on since): the producer sees at most this many, the consumer at least this many.
    size_t size() const {
        const uint64_t tail = tail_.load(std::memory_order_acquire);
        const uint64_t head = head_.load(std::memory_order_acquire);
        return head >= tail ? size_t(head - tail) : 0;
    }
    uint64_t pushedTotal() const { return head_.load(std::memory_order_acquire); }
    uint64_t poppedTotal() const { return tail_.load(std::memory_order_acquire); }

private:
    // At most two pieces: up to the end of the array, then from its start.
    void copyIn(uint64_t at, const T* data, size_t count) {
        const size_t first = std::min(count, capacity() - size_t(at & mask_));
        std::copy_n(data, first, slots_.get() + (at & mask_));
        std::copy_n(data + first, count - first, slots_.get());
    }
    void copyOut(uint64_t at, T* out, size_t count) const {
        const size_t first = std::min(count, capacity() - size_t(at & mask_));
        std::copy_n(slots_.get() + (at & mask_), first, out);
        std::copy_n(slots_.get(), count - first, out + first);
    }

    size_t mask_ = 0;
    std::unique_ptr<T[]> slots_;
    alignas(64) std::atomic<uint64_t> head_{0}; // own cache lines: the two threads do not
    alignas(64) std::atomic<uint64_t> tail_{0}; // invalidate each other's counter on every write
};

} // namespace clothtear::audio
