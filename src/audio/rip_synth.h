// The rip synthesizer: sound events (sound_events.h) in, 48 kHz stereo float out. No device, no GL.
//
// A tear is heard as grains: a few milliseconds of band-passed noise under a Hann window (granular
// synthesis, as Cirio et al. 2016 build crumpling from clicks). What each part follows:
//   count    grainsPerMetre x the length of cloth torn: a rip sounds the same at any resolution
//            (twice the springs of half the length give the same grains);
//   when     spread over `spread` seconds after the tear, at seeded random offsets;
//   energy   each grain carries gain^2 x energyDensity / referenceDensity, whatever its pitch and
//            length (the band-pass and the window are normalised), so the sound's energy is
//            proportional to sum(energyDensity x length): the same per metre of rip at any resolution;
//   pitch    the tear speed (m/s of cloth torn, smoothed over rateTime): a slow rip is a low creak of
//            longer grains, a fast rip a bright hiss of short ones;
//   pan      the event's pan, equal power;
//   mode     a one-point split (two parts letting go) is a low, wide pop;
//   impact   tears of a ball hit are darker and wider, and the hit starts with a thump (a decaying
//            70 Hz sine) once per contact;
//   knife    a blade cuts fibres whether they were tense or not: its grains carry at least
//            knifeEnergy and are a short, high, ringing snip (8 kHz, Q 4, 2.5 ms), whatever the
//            speed; their count follows the length cut, as a rip's does.
// Deterministic: the noise of grain i is a hash of (seed, i, sample), so the output does not depend
// on how the caller cuts the rendering into blocks.
#pragma once
#include "sound_events.h"

#include <cstdint>
#include <vector>

namespace clothtear::audio {

struct SynthSettings {
    int sampleRate = 48000;           // Hz
    float grainsPerMetre = 400.f;     // 1/m of cloth torn: one grain per 2.5 mm of rip
    float spread = 1.f / 60.f;        // s: a tear's grains start within one frame after it
    float gain = 0.08f;               // peak-ish amplitude of a grain at referenceDensity
    float referenceDensity = 2.7f;    // J/m^2: 60 N/m at strain 0.3 (the default material tearing)
    float rateTime = 0.05f;           // s: the tear speed is the cloth torn over about this long
    float thumpGain = 0.3f;           // amplitude of a ball hit's thump
    float knifeEnergy = 0.3f;         // relative to referenceDensity: the least a knife's grain carries
    uint64_t seed = 0x5eed;           // the noise and the grains' offsets
};

class RipSynth {
public:
    explicit RipSynth(const SynthSettings& settings = {});
    // Schedules the grains of one event (time in s from the first sample; events in time order).
    // A time before what was already rendered starts at the next sample.
    void add(const SoundEvent& e);
    // Renders the next `frames` stereo frames into out (2 x frames floats, left, right, ...).
    void render(float* out, size_t frames);
    uint64_t rendered() const { return cursor_; } // stereo frames rendered so far
    uint64_t grains() const { return grainCount_; } // grains scheduled so far
    const SynthSettings& settings() const { return s_; }

private:
    struct Grain {
        int64_t start = 0;         // sample frame of its first sample
        int length = 0;            // samples
        int pos = 0;               // next sample to render
        float left = 0, right = 0; // channel gains
        bool thump = false;        // a sine thump instead of noise
        float b0 = 0, b2 = 0, a1 = 0, a2 = 0; // band-pass biquad (b1 = 0)
        float z1 = 0, z2 = 0;      // its state (transposed direct form II)
        float omega = 0;           // thump: rad per sample
        uint64_t seed = 0;
    };
    void addGrain(Grain g);
    float nextUniform(); // [0, 1), for the grains' offsets

    SynthSettings s_;
    std::vector<Grain> grains_;
    uint64_t cursor_ = 0;
    uint64_t grainCount_ = 0;
    uint64_t rng_;
    double carry_ = 0;          // grains owed by the torn length so far (fraction)
    double rate_ = 0;           // m/s of cloth torn, smoothed
    double rateAt_ = 0;         // s, when rate_ was last updated
    double lastThump_ = -1e30;  // s
};

} // namespace clothtear::audio
