// The soundtrack of a run (soundtrack.h).
#include "soundtrack.h"

#include <cmath>

namespace clothtear::audio {

Soundtrack::Soundtrack(const World& world, const SynthSettings& settings)
    : listener_(world), synth_(settings), start_(world.time) {}

void Soundtrack::afterFrame(const World& world) {
    events_.clear();
    listener_.collect(world, events_);
    for (SoundEvent e : events_) {
        e.time -= start_;
        synth_.add(e);
    }
    // The length comes from the time itself, not from a sum of frames: no drift, to the sample.
    const int64_t target = std::llround((world.time - start_) * synth_.settings().sampleRate);
    const int64_t todo = target - int64_t(synth_.rendered());
    if (todo <= 0) return;
    const size_t at = samples_.size();
    samples_.resize(at + 2 * size_t(todo));
    synth_.render(samples_.data() + at, size_t(todo));
}

} // namespace clothtear::audio
