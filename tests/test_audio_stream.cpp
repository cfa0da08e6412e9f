// The live sound's plumbing (src/audio): the lock-free ring the app's audio device pulls from
// (spsc_ring.h), and the sound stream the app feeds it with (sound_stream.h).
#include "sound_stream.h"
#include "soundtrack.h"
#include "spsc_ring.h"

#include "clothtear/history.h"
#include "clothtear/scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numeric>
#include <thread>
#include <vector>

using namespace clothtear;
using namespace clothtear::audio;

TEST(SpscRing, CapacityIsAPowerOfTwoAndEmptyAndFullAreExact) {
    SpscRing<int> ring(5);
    EXPECT_EQ(ring.capacity(), 8u);
    int out[16] = {};
    EXPECT_EQ(ring.pop(out, 4), 0u) << "empty: nothing to pop, and pop does not wait";
    std::vector<int> in(12);
    std::iota(in.begin(), in.end(), 100);
    EXPECT_EQ(ring.push(in.data(), 12), 8u) << "takes what fits";
    EXPECT_EQ(ring.size(), 8u);
    EXPECT_EQ(ring.push(in.data(), 1), 0u) << "full: push takes nothing, and does not wait";
    EXPECT_EQ(ring.pop(out, 3), 3u);
    EXPECT_EQ(ring.push(in.data() + 8, 4), 3u) << "room for the three popped";
    EXPECT_EQ(ring.pop(out + 3, 16), 8u);
    for (int k = 0; k < 11; ++k) EXPECT_EQ(out[k], 100 + k) << "element " << k;
    EXPECT_EQ(ring.size(), 0u);
    EXPECT_EQ(ring.pushedTotal(), 11u);
    EXPECT_EQ(ring.poppedTotal(), 11u);
}

// Pushes and pops of every length across the end of the array: the elements come out in order.
TEST(SpscRing, WrapsAroundTheEndOfItsArray) {
    SpscRing<uint32_t> ring(8);
    uint32_t next = 0, expected = 0;
    std::vector<uint32_t> in, out(8);
    for (size_t start = 0; start < 8; ++start) // every offset of the array's end
        for (size_t n = 1; n <= 8; ++n) {
            // Move the ring's position to `start` past a multiple of 8, then push n and pop n.
            while (ring.pushedTotal() % 8 != start) {
                ring.push(&next, 1);
                ASSERT_EQ(ring.pop(out.data(), 1), 1u);
                ASSERT_EQ(out[0], expected++);
                ++next;
            }
            in.resize(n);
            for (uint32_t& v : in) v = next++;
            ASSERT_EQ(ring.push(in.data(), n), n);
            ASSERT_EQ(ring.pop(out.data(), 8), n);
            for (size_t k = 0; k < n; ++k) ASSERT_EQ(out[k], expected++) << "start " << start << ", n " << n << ", k " << k;
        }
}

// Two threads, a small ring (many wrap-arounds), pushes and pops of varying lengths: every element
// comes out exactly once and in order. A wrong index or wrap shows up as an element out of order
// (a second piece written one slot off fails here and in WrapsAround...). A counter published before
// its elements are written is a race this loop rarely loses on x86: that is ThreadSanitizer's to see
// (this loop built with g++ -fsanitize=thread: no report; with head_ stored before the copy: "data
// race" in push and pop).
TEST(SpscRing, TwoThreadsPassFourMillionElementsInOrder) {
    constexpr uint64_t kCount = 4'000'000;
    SpscRing<uint64_t> ring(64);
    std::thread producer([&ring] {
        std::vector<uint64_t> chunk(80);
        uint64_t next = 0, rng = 1;
        while (next < kCount) {
            rng = rng * 6364136223846793005ull + 1442695040888963407ull;
            const size_t want = std::min<uint64_t>(1 + (rng >> 58), kCount - next); // 1 .. 64
            for (size_t k = 0; k < want; ++k) chunk[k] = next + k;
            const size_t took = ring.push(chunk.data(), want);
            next += took;
            if (!took) std::this_thread::yield();
        }
    });
    std::vector<uint64_t> chunk(80);
    uint64_t expected = 0, rng = 7, errors = 0, firstBad = 0;
    while (expected < kCount) {
        rng = rng * 6364136223846793005ull + 1442695040888963407ull;
        const size_t got = ring.pop(chunk.data(), 1 + (rng >> 58));
        for (size_t k = 0; k < got; ++k, ++expected)
            if (chunk[k] != expected && errors++ == 0) firstBad = expected;
        if (!got) std::this_thread::yield();
    }
    producer.join();
    EXPECT_EQ(errors, 0u) << "first element out of order: " << firstBad;
    EXPECT_EQ(ring.pushedTotal(), kCount);
    EXPECT_EQ(ring.poppedTotal(), kCount);
    EXPECT_EQ(ring.size(), 0u);
}

// Without a rebase the stream is the headless runner's soundtrack, sample for sample.
TEST(SoundStream, IsTheSoundtrackOfTheSameFrames) {
    World w;
    ASSERT_EQ(loadScene(w, "ball-r0.5-v3", {}), "");
    SoundStream stream(w);
    Soundtrack track(w);
    std::vector<float> out;
    size_t frames = 0;
    for (int f = 0; f < 30; ++f) {
        w.step();
        frames += stream.afterFrame(w, out);
        track.afterFrame(w);
    }
    ASSERT_GT(w.tearLog.total(), 0u);
    EXPECT_EQ(frames, 24000u);
    ASSERT_EQ(out.size(), track.samples().size());
    EXPECT_TRUE(out == track.samples());
    EXPECT_GT(std::inner_product(out.begin(), out.end(), out.begin(), 0.0), 0.0);
}

// The app's undo: the world goes back to a checkpoint before the tears and steps on. The stream
// rebases: it goes on from its last sample, as long as the frames stepped (without the rebase the
// world's clock, now behind the stream's, would render nothing for 30 frames), and the tears after
// the restore sound as loud as those of a stream started on that world.
TEST(SoundStream, RebasedOnARestoredPastGoesOnWithoutHearingOldTearsAgain) {
    World w;
    ASSERT_EQ(loadScene(w, "ball-r0.5-v3", {}), "");
    for (int f = 0; f < 10; ++f) w.step(); // the ball in flight, no tears yet
    ASSERT_EQ(w.tearLog.total(), 0u);
    const Checkpoint past = Checkpoint::take(w);
    SoundStream stream(w);
    std::vector<float> out;
    for (int f = 0; f < 30; ++f) {
        w.step();
        stream.afterFrame(w, out);
    }
    ASSERT_GT(w.tearLog.total(), 0u) << "the ball is meant to tear by frame 40";
    const size_t before = out.size();
    past.restore(w);
    ASSERT_EQ(w.tearLog.total(), 0u);
    stream.rebase(w);
    World fresh;
    ASSERT_EQ(loadScene(fresh, "ball-r0.5-v3", {}), "");
    for (int f = 0; f < 10; ++f) fresh.step();
    SoundStream reference(fresh);
    std::vector<float> ref;
    size_t frames = 0;
    for (int f = 0; f < 30; ++f) {
        w.step();
        fresh.step();
        frames += stream.afterFrame(w, out);
        reference.afterFrame(fresh, ref);
    }
    EXPECT_EQ(frames, 24000u) << "30 frames of 1/60 s, whatever the world's clock did";
    EXPECT_EQ(stream.rendered(), 48000u);
    ASSERT_EQ(out.size() - before, ref.size());
    // The grains scheduled before the restore may ring on for a frame (a rebase lets them play out):
    // compare from the third frame on. The tears are the same; the grains' random offsets and noise
    // seeds are not (the synth had drawn grains before), so the energies agree within 25 %.
    const std::vector<float> after(out.begin() + std::ptrdiff_t(before), out.end());
    double e = 0, eRef = 0;
    for (size_t k = 2 * 1600; k < after.size(); ++k) e += double(after[k]) * after[k], eRef += double(ref[k]) * ref[k];
    ASSERT_GT(eRef, 0.0);
    EXPECT_NEAR(e / eRef, 1.0, 0.25) << "the restored run's tears, heard once, as loud as a fresh run's";
}
