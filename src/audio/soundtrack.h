// The soundtrack of a run: a TearListener and a RipSynth kept in step with a World, frame by frame.
// The headless runner writes it with --audio-out (wav_file.h).
#pragma once
#include "rip_synth.h"
#include "sound_events.h"

#include <vector>

namespace clothtear::audio {

class Soundtrack {
public:
    // Starts at the world's current time: sample 0 is world.time.
    explicit Soundtrack(const World& world, const SynthSettings& settings = {});
    // After World::step: the frame's tears become grains and the track grows to the world's time
    // (round((time - start) x sample rate) stereo frames in all).
    void afterFrame(const World& world);
    const std::vector<float>& samples() const { return samples_; } // interleaved stereo
    size_t frames() const { return samples_.size() / 2; }
    int sampleRate() const { return synth_.settings().sampleRate; }
    const RipSynth& synth() const { return synth_; }

private:
    TearListener listener_;
    RipSynth synth_;
    double start_;
    std::vector<SoundEvent> events_; // this frame's, reused
    std::vector<float> samples_;
};

} // namespace clothtear::audio
