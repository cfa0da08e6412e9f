// Live sound through SDL2's audio subsystem (audio_out.h).
#include "audio_out.h"

#include <SDL.h>

#include <algorithm>
#include <cmath>

namespace clothtear::app {
namespace {

// 8192 stereo frames (170 ms at 48 kHz): room for the latency cap with a frame of sound to spare.
constexpr size_t kRingFrames = 8192;
// The device's own buffer: 512 frames, 10.7 ms at 48 kHz.
constexpr int kDeviceFrames = 512;

} // namespace

AudioOut::AudioOut() : ring_(2 * kRingFrames) {}

AudioOut::~AudioOut() { close(); }

std::string AudioOut::open(int sampleRate) {
    close();
    driver_.clear();
    sampleRate_ = sampleRate;
    if (SDL_InitSubSystem(SDL_INIT_AUDIO) != 0) return std::string("no audio (SDL: ") + SDL_GetError() + ")";
    const char* driver = SDL_GetCurrentAudioDriver();
    // ALSA without a sound card lists no device, and opening its default anyway prints eight lines
    // of its own errors on stderr: when the driver knows it has nothing, do not ask. (-1: the driver
    // cannot list its devices; then trying is the only way to know.)
    if (SDL_GetNumAudioDevices(0) == 0) {
        const std::string why = std::string("no audio output device (SDL driver ") + (driver ? driver : "?") + " lists none)";
        SDL_QuitSubSystem(SDL_INIT_AUDIO);
        return why;
    }
    SDL_AudioSpec want{}, have{};
    want.freq = sampleRate;
    want.format = AUDIO_F32SYS;
    want.channels = 2;
    want.samples = kDeviceFrames;
    want.callback = &AudioOut::callback;
    want.userdata = this;
    // No changes allowed: SDL converts to what the device takes, the callback always sees this format.
    const SDL_AudioDeviceID id = SDL_OpenAudioDevice(nullptr, 0, &want, &have, 0);
    if (id == 0) {
        const std::string why = std::string("cannot open the audio output device (SDL: ") + SDL_GetError() + ")";
        SDL_QuitSubSystem(SDL_INIT_AUDIO);
        return why;
    }
    device_ = id;
    driver_ = driver ? driver : "?";
    SDL_PauseAudioDevice(device_, 0); // start playing (silence until the first push)
    return {};
}

void AudioOut::close() {
    if (device_ == 0) return;
    SDL_CloseAudioDevice(device_); // waits for a running callback to return
    device_ = 0; // driver_ stays: the exit report names what played
    SDL_QuitSubSystem(SDL_INIT_AUDIO);
}

size_t AudioOut::push(const float* interleaved, size_t frames) {
    if (device_ == 0) return 0;
    pushed_ += frames;
    // ring_.size() only shrinks behind our back (the device pops): the room we see is there.
    const size_t cap = std::min(kRingFrames, size_t(std::max(0.0, maxLatency) * sampleRate_));
    const size_t queued = ring_.size() / 2;
    const size_t room = cap > queued ? cap - queued : 0;
    const size_t take = std::min(frames, room);
    // Keep the newest sound when some must go: the tail end of this frame is what comes next.
    const size_t skip = frames - take;
    ring_.push(interleaved + 2 * skip, 2 * take);
    dropped_ += skip;
    return take;
}

void AudioOut::callback(void* self, uint8_t* stream, int bytes) {
    static_cast<AudioOut*>(self)->fill(reinterpret_cast<float*>(stream), size_t(bytes) / (2 * sizeof(float)));
}

// Device thread: no lock, no allocation, no wait.
void AudioOut::fill(float* out, size_t frames) {
    callbacks_.fetch_add(1, std::memory_order_relaxed);
    const size_t got = ring_.pop(out, 2 * frames) / 2;
    std::fill(out + 2 * got, out + 2 * frames, 0.f); // an underrun plays silence
    if (got < frames) underrun_.fetch_add(frames - got, std::memory_order_relaxed);
    // The gain glides linearly from the last callback's to the new one over this block.
    const float target = muted_.load(std::memory_order_relaxed) ? 0.f
                                                                 : std::clamp(volume_.load(std::memory_order_relaxed), 0.f, 1.f);
    const float start = gain_, step = frames ? (target - start) / float(frames) : 0.f;
    for (size_t i = 0; i < frames; ++i) {
        const float g = start + step * float(i + 1);
        out[2 * i] *= g;
        out[2 * i + 1] *= g;
    }
    gain_ = target;
}

AudioOutCounters AudioOut::counters() const {
    AudioOutCounters c;
    c.pushed = pushed_;
    c.dropped = dropped_;
    c.played = ring_.poppedTotal() / 2;
    c.underrun = underrun_.load(std::memory_order_relaxed);
    c.callbacks = callbacks_.load(std::memory_order_relaxed);
    return c;
}

} // namespace clothtear::app
