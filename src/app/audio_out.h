// Live sound: the default audio output device (SDL2's audio subsystem, see src/app/README.md for why
// SDL2), fed by a lock-free ring (src/audio/spsc_ring.h).
//
//   main thread (simulation)                          SDL's audio thread
//   SoundStream::afterFrame -> push() ---> SpscRing ---> callback -> x gain -> device
//                              never waits: drops       never waits: an underrun plays silence
//                              what does not fit
//
// Without a device (no sound card, Xvfb, CI, SDL_AUDIODRIVER naming nothing usable) open() says why
// in one line and every later call is a cheap no-op: the app runs silently.
#pragma once
#include "spsc_ring.h"

#include <atomic>
#include <cstdint>
#include <string>

namespace clothtear::app {

struct AudioOutCounters {
    uint64_t pushed = 0;    // stereo frames the simulation handed in
    uint64_t dropped = 0;   // of those, frames that found the queue at its latency cap
    uint64_t played = 0;    // frames the device took from the queue
    uint64_t underrun = 0;  // frames of silence the device got because the queue was empty
    uint64_t callbacks = 0; // device callbacks
};

class AudioOut {
public:
    AudioOut();
    ~AudioOut();
    AudioOut(const AudioOut&) = delete;
    AudioOut& operator=(const AudioOut&) = delete;

    // Opens the default output device, stereo float at sampleRate, and starts it. "" when it plays,
    // otherwise why not (one line for the log; the app goes on silently).
    std::string open(int sampleRate);
    void close();
    bool isOpen() const { return device_ != 0; }
    const std::string& driver() const { return driver_; } // SDL's driver that played ("" if none)

    // Simulation thread: queues interleaved stereo frames for the device; never blocks. Frames that
    // would put more than maxLatency seconds in the queue are dropped (counted). Returns the frames
    // queued. A no-op without a device.
    size_t push(const float* interleaved, size_t frames);

    // Read by the device thread at its next callback; the gain glides over one callback (no click).
    void setVolume(float volume) { volume_.store(volume, std::memory_order_relaxed); }
    void setMuted(bool muted) { muted_.store(muted, std::memory_order_relaxed); }

    AudioOutCounters counters() const;
    double maxLatency = 0.1; // s: the most sound queued ahead of the device (the rest is dropped)

private:
    static void callback(void* self, uint8_t* stream, int bytes);
    void fill(float* out, size_t frames);

    uint32_t device_ = 0; // SDL_AudioDeviceID; 0 = none
    std::string driver_;
    int sampleRate_ = 48000;
    audio::SpscRing<float> ring_; // interleaved stereo: only whole frames go in and come out
    std::atomic<float> volume_{1.f};
    std::atomic<bool> muted_{false};
    float gain_ = 0.f; // device thread: the gain the last callback ended on
    // counters: pushed and dropped written by the simulation thread, the others by the device's
    uint64_t pushed_ = 0, dropped_ = 0;
    std::atomic<uint64_t> underrun_{0}, callbacks_{0};
};

} // namespace clothtear::app
