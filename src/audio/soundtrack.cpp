// The soundtrack of a run (soundtrack.h).
#include "soundtrack.h"

namespace clothtear::audio {

Soundtrack::Soundtrack(const World& world, const SynthSettings& settings) : stream_(world, settings) {}

void Soundtrack::afterFrame(const World& world) { stream_.afterFrame(world, samples_); }

} // namespace clothtear::audio
