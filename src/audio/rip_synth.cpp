// The rip synthesizer (rip_synth.h): grains scheduled from sound events, rendered block by block.
#include "rip_synth.h"

#include <algorithm>
#include <cmath>

namespace clothtear::audio {
namespace {

constexpr double kPi = 3.14159265358979323846;

// splitmix64: a well-mixed hash, so neighbouring (grain, sample) pairs give independent noise.
uint64_t mix(uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

// White noise in [-1, 1) (variance 1/3) as a function of the grain's seed and the sample.
float noiseAt(uint64_t seed, int i) { return float(int64_t(mix(seed ^ uint64_t(i) * 0xd1b54a32d192ed03ull) >> 40)) / float(1 << 23) - 1.f; }

} // namespace

RipSynth::RipSynth(const SynthSettings& settings) : s_(settings), rng_(mix(settings.seed)) {}

float RipSynth::nextUniform() {
    rng_ = mix(rng_);
    return float(rng_ >> 40) / float(1 << 24);
}

void RipSynth::addGrain(Grain g) {
    g.start = std::max<int64_t>(g.start, int64_t(cursor_));
    g.seed = mix(s_.seed + ++grainCount_);
    grains_.push_back(g);
}

void RipSynth::add(const SoundEvent& e) {
    const double fs = s_.sampleRate;
    // Tear speed: an exponentially weighted sum of the lengths torn, / rateTime (m/s). Twice the
    // events of half the length give the same rate.
    rate_ *= std::exp(-std::max(0.0, e.time - rateAt_) / s_.rateTime);
    rateAt_ = std::max(rateAt_, e.time);
    rate_ += e.length / s_.rateTime;
    double energy = std::max(0.f, e.energyDensity) / s_.referenceDensity; // relative
    if (e.mode == TearMode::Knife) energy = std::max(energy, double(s_.knifeEnergy));
    // Equal-power pan.
    const double angle = (std::clamp(e.pan, -1.f, 1.f) + 1.0) * kPi / 4;
    const float left = float(std::cos(angle)), right = float(std::sin(angle));

    if (e.impact && e.time - lastThump_ > 2 * kImpactWindow) {
        // The hit itself: 150 ms of a 70 Hz sine decaying in 40 ms; once per contact.
        lastThump_ = e.time;
        Grain g;
        g.thump = true;
        g.start = std::llround(e.time * fs);
        g.length = int(0.15 * fs);
        g.omega = float(2 * kPi * 70.0 / fs);
        const float a = s_.thumpGain * float(std::sqrt(std::min(energy, 4.0)));
        g.left = a * left, g.right = a * right;
        addGrain(g);
    }
    if (!(energy > 0)) return;

    // Pitch and grain length from the tear speed: 1 m/s -> 1.2 kHz, 6 ms; 10 m/s -> 3.8 kHz, 3 ms.
    const double speed = std::max(rate_, 1e-3);
    double centre = std::clamp(1200.0 * std::sqrt(speed), 300.0, 6000.0);
    double q = e.mode == TearMode::WeakPoint ? 2.5 : 2.0; // a running tear rings a little more
    double seconds = std::clamp(0.006 * std::pow(speed, -0.3), 0.002, 0.012);
    if (e.mode == TearMode::OnePoint) centre *= 0.5, q = 0.7, seconds *= 2; // two parts let go: a pop
    if (e.impact) centre *= 0.6, q = 1.0;                                    // a hit: darker, wider
    if (e.mode == TearMode::Knife) centre = 8000.0, q = 4.0, seconds = 0.0025; // a blade: a snip
    centre = std::min(centre, 0.4 * fs);
    const int length = std::max(8, int(seconds * fs));
    // RBJ band-pass, 0 dB at the centre: b = (alpha, 0, -alpha) / a0, a = (1, -2 cos w, 1 - alpha) / a0.
    const double w = 2 * kPi * centre / fs, alpha = std::sin(w) / (2 * q), a0 = 1 + alpha;
    // Energy normalisation: white noise of variance 1/3 through this filter keeps about
    // (pi/2 x bandwidth) / (fs/2) of its power (bandwidth = centre / q), the Hann window 3/8 of what
    // is left: scale so that every grain carries gain^2 x energy x (5 ms of samples) / 3.
    const double kept = (kPi / 2) * (centre / q) / (fs / 2) * 0.375 * length;
    const double amplitude = s_.gain * std::sqrt(energy * 0.005 * fs / kept);

    // The 1e-4 keeps float lengths from losing a grain: 25 tears of 0.02f m are 200 grains, not 199.
    carry_ += double(e.length) * s_.grainsPerMetre;
    for (; carry_ >= 1 - 1e-4; carry_ -= 1) {
        Grain g;
        g.start = std::llround((e.time + nextUniform() * s_.spread) * fs);
        g.length = length;
        g.left = float(amplitude) * left, g.right = float(amplitude) * right;
        g.b0 = float(alpha / a0), g.b2 = float(-alpha / a0);
        g.a1 = float(-2 * std::cos(w) / a0), g.a2 = float((1 - alpha) / a0);
        addGrain(g);
    }
}

void RipSynth::render(float* out, size_t frames) {
    std::fill(out, out + 2 * frames, 0.f);
    const int64_t begin = int64_t(cursor_), end = begin + int64_t(frames);
    for (Grain& g : grains_) {
        const int64_t from = std::max(begin, g.start + g.pos), to = std::min(end, g.start + g.length);
        for (int64_t n = from; n < to; ++n, ++g.pos) {
            const int i = g.pos;
            const float window = 0.5f - 0.5f * std::cos(float(2 * kPi) * (float(i) + 0.5f) / float(g.length));
            float y;
            if (g.thump) {
                const float t = float(i) / float(s_.sampleRate);
                y = std::sin(g.omega * float(i)) * std::exp(-t / 0.04f) * std::min(1.f, t / 0.001f);
            } else {
                // Transposed direct form II, b1 = 0.
                const float x = noiseAt(g.seed, i);
                y = g.b0 * x + g.z1;
                g.z1 = g.z2 - g.a1 * y;
                g.z2 = g.b2 * x - g.a2 * y;
                y *= window;
            }
            out[2 * (n - begin)] += g.left * y;
            out[2 * (n - begin) + 1] += g.right * y;
        }
    }
    // Grains that ended are dropped, the others keep their order (the sum's order, so the output).
    std::erase_if(grains_, [end](const Grain& g) { return g.start + g.length <= end; });
    for (size_t k = 0; k < 2 * frames; ++k) out[k] = std::clamp(out[k], -1.f, 1.f);
    cursor_ = uint64_t(end);
}

} // namespace clothtear::audio
