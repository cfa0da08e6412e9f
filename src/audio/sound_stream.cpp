// The sound of a World as a stream (sound_stream.h).
#include "sound_stream.h"

#include <cmath>

namespace clothtear::audio {

SoundStream::SoundStream(const World& world, const SynthSettings& settings)
    : listener_(world), synth_(settings), worldBase_(world.time), streamBase_(0) {}

void SoundStream::rebase(const World& world) {
    listener_ = TearListener(world);
    worldBase_ = world.time;
    streamBase_ = synth_.rendered();
}

size_t SoundStream::afterFrame(const World& world, std::vector<float>& out) {
    const double fs = synth_.settings().sampleRate;
    const double streamStart = double(streamBase_) / fs; // s on the stream's clock at worldBase_
    events_.clear();
    listener_.collect(world, events_);
    for (SoundEvent e : events_) {
        e.time = streamStart + (e.time - worldBase_);
        synth_.add(e);
    }
    // The length comes from the time itself, not from a sum of frames: no drift, to the sample.
    const int64_t target = int64_t(streamBase_) + std::llround((world.time - worldBase_) * fs);
    const int64_t todo = target - int64_t(synth_.rendered());
    if (todo <= 0) return 0;
    const size_t at = out.size();
    out.resize(at + 2 * size_t(todo));
    synth_.render(out.data() + at, size_t(todo));
    return size_t(todo);
}

} // namespace clothtear::audio
