// The soundtrack of a run: its SoundStream (sound_stream.h) kept whole, frame by frame. The headless
// runner writes it with --audio-out (wav_file.h); the app keeps its own stream, played and kept.
#pragma once
#include "sound_stream.h"

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
    int sampleRate() const { return stream_.sampleRate(); }
    const RipSynth& synth() const { return stream_.synth(); }

private:
    SoundStream stream_;
    std::vector<float> samples_;
};

} // namespace clothtear::audio
