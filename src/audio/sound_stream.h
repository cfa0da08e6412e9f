// The sound of a World as an endless stream, frame by frame: a TearListener and a RipSynth kept in
// step with the world's time. What the app plays live (src/app/audio_out.h) and what the headless
// runner's soundtrack (soundtrack.h) is made of; the same frames give the same samples in both.
//
// The stream's clock is its own: sample n is n / sampleRate seconds after the stream started. A
// world's time maps onto it from a base (the world's time at the last start or rebase, and the
// stream's sample then), so a world that jumps (the app's undo, its timeline, a scene loaded, a
// reset) rebases: its earlier tears are not heard again and the stream goes on without a gap or an
// overlap.
#pragma once
#include "rip_synth.h"
#include "sound_events.h"

#include <vector>

namespace clothtear::audio {

class SoundStream {
public:
    // Starts at the world's current time: stream sample 0 is world.time.
    explicit SoundStream(const World& world, const SynthSettings& settings = {});
    // The world was replaced or jumped in time: from now on its time maps onto the stream's next
    // sample, and only tears logged after this call are heard (its rest frame is read again for
    // panning). Grains already scheduled play on.
    void rebase(const World& world);
    // After World::step: the frame's tears become grains, and the stream is rendered up to the
    // world's time, appended to out (interleaved stereo). Returns the stereo frames appended (0 when
    // the world's time did not move past what was rendered).
    size_t afterFrame(const World& world, std::vector<float>& out);

    uint64_t rendered() const { return synth_.rendered(); } // stereo frames so far
    int sampleRate() const { return synth_.settings().sampleRate; }
    const RipSynth& synth() const { return synth_; }

private:
    TearListener listener_;
    RipSynth synth_;
    double worldBase_;     // s, the world's time at the start or the last rebase
    uint64_t streamBase_;  // the stream's sample at that moment
    std::vector<SoundEvent> events_; // this frame's, reused
};

} // namespace clothtear::audio
