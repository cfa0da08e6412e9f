// The sound of tearing (src/audio): the synthesizer on hand-made events, and the soundtrack of real
// scenes run in-process, checked against the frames in which the tear log grew.
#include "rip_synth.h"
#include "soundtrack.h"
#include "wav_file.h"

#include "clothtear/scenes.h"
#include "omp_threads.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

using namespace clothtear;
using namespace clothtear::audio;

namespace {

constexpr size_t kFrame = 800; // stereo frames per 1/60 s at 48 kHz

double sumSquares(const std::vector<float>& s, size_t from, size_t to) {
    double e = 0;
    for (size_t k = from; k < to; ++k) e += double(s[k]) * s[k];
    return e;
}
double sumSquares(const std::vector<float>& s) { return sumSquares(s, 0, s.size()); }

// RMS of each 1/60 s frame of an interleaved stereo track.
std::vector<double> frameRms(const std::vector<float>& s) {
    std::vector<double> rms;
    for (size_t at = 0; at + 2 * kFrame <= s.size(); at += 2 * kFrame)
        rms.push_back(std::sqrt(sumSquares(s, at, at + 2 * kFrame) / (2 * kFrame)));
    return rms;
}

// Zero crossings per sounding sample of the left channel: a brightness measure (a band-passed noise
// at centre f crosses about 2 f / fs times per sample). Silence between grains does not count.
double crossingRate(const std::vector<float>& s) {
    size_t crossings = 0, n = 0;
    for (size_t k = 2; k < s.size(); k += 2) {
        if (s[k] == 0 && s[k - 2] == 0) continue;
        ++n;
        crossings += (s[k] > 0) != (s[k - 2] > 0);
    }
    return double(crossings) / double(std::max<size_t>(n, 1));
}

std::vector<float> renderAll(RipSynth& synth, size_t frames, size_t block) {
    std::vector<float> out(2 * frames);
    for (size_t at = 0; at < frames; at += block) synth.render(out.data() + 2 * at, std::min(block, frames - at));
    return out;
}

// A rip of `length` metres torn at `speed` m/s by springs of rest length `spring`, starting at t = 0.1 s.
std::vector<SoundEvent> rip(double length, double speed, double spring, float pan = 0) {
    std::vector<SoundEvent> events;
    const int n = int(std::lround(length / spring));
    for (int k = 0; k < n; ++k) {
        SoundEvent e;
        e.time = 0.1 + k * spring / speed;
        e.length = float(spring);
        e.energyDensity = 2.7f;
        e.pan = pan;
        events.push_back(e);
    }
    return events;
}

std::vector<float> play(const std::vector<SoundEvent>& events, size_t frames, size_t block = 4096) {
    RipSynth synth;
    for (const SoundEvent& e : events) synth.add(e);
    return renderAll(synth, frames, block);
}

} // namespace

TEST(RipSynth, NoEventsIsExactlySilentAndEventsAreNot) {
    const std::vector<float> quiet = play({}, 48000);
    EXPECT_EQ(sumSquares(quiet), 0.0);
    const std::vector<float> loud = play(rip(0.2, 1.0, 0.02), 48000);
    EXPECT_GT(sumSquares(loud), 1.0) << "a 20 cm rip is heard";
    for (float x : loud) ASSERT_LE(std::abs(x), 1.f);
}

// The noise is a function of (grain, sample), and grains keep their order: the block size the
// caller renders with (a frame headless, the device's buffer in an app) changes no sample.
TEST(RipSynth, OutputDoesNotDependOnTheBlockSize) {
    const std::vector<SoundEvent> events = rip(0.5, 2.0, 0.01);
    EXPECT_EQ(play(events, 30000, 800), play(events, 30000, 37));
}

// Grains per metre of tear, not per spring: the same rip torn by twice the springs of half the
// length has the same grains and the same energy (within the spread of random noise: 5%).
TEST(RipSynth, TheSameRipAtTwiceTheResolutionSoundsTheSame) {
    RipSynth coarse, fine;
    for (const SoundEvent& e : rip(0.5, 2.0, 0.02)) coarse.add(e);
    for (const SoundEvent& e : rip(0.5, 2.0, 0.01)) fine.add(e);
    EXPECT_EQ(coarse.grains(), 200u); // 0.5 m x 400 per metre
    EXPECT_EQ(fine.grains(), 200u);
    const double a = sumSquares(renderAll(coarse, 30000, 800)), b = sumSquares(renderAll(fine, 30000, 800));
    EXPECT_NEAR(b / a, 1.0, 0.05) << "coarse " << a << ", fine " << b;
}

// Loudness follows the energy released: four times the energy density, four times the energy.
TEST(RipSynth, EnergyFollowsTheEnergyReleased) {
    std::vector<SoundEvent> weak = rip(0.5, 2.0, 0.01), strong = weak;
    for (SoundEvent& e : strong) e.energyDensity *= 4;
    const double a = sumSquares(play(weak, 30000)), b = sumSquares(play(strong, 30000));
    EXPECT_NEAR(b / a, 4.0, 0.01);
}

// A slow rip is a low creak, a fast one a bright hiss (and a louder one: more grains per second).
TEST(RipSynth, AFastRipIsBrighterThanASlowOne) {
    const std::vector<float> slow = play(rip(0.3, 0.3, 0.01), 96000), fast = play(rip(0.3, 6.0, 0.01), 96000);
    EXPECT_GT(crossingRate(fast), 0.0);
    EXPECT_GT(crossingRate(fast) / crossingRate(slow), 1.5)
        << "zero crossings per sample: slow " << crossingRate(slow) << ", fast " << crossingRate(fast);
}

TEST(RipSynth, PanPutsATearOnItsSide) {
    const std::vector<float> left = play(rip(0.2, 1.0, 0.01, -1.f), 48000);
    double l = 0, r = 0;
    for (size_t k = 0; k < left.size(); k += 2) l += double(left[k]) * left[k], r += double(left[k + 1]) * left[k + 1];
    EXPECT_GT(l, 1.0);
    EXPECT_LT(r, 1e-9 * l);
}

// A ball hit starts with a thump: energy below 200 Hz that a rip of the same tears has not. A
// one-pole low-pass (about 150 Hz) separates it.
TEST(RipSynth, ABallHitHasItsOwnThump) {
    std::vector<SoundEvent> hit = rip(0.2, 3.0, 0.01);
    for (SoundEvent& e : hit) e.impact = true;
    auto lowEnergy = [](const std::vector<float>& s) {
        double y = 0, e = 0;
        const double a = 1 - std::exp(-2 * 3.14159265 * 150 / 48000.0);
        for (size_t k = 0; k < s.size(); k += 2) y += a * (s[k] - y), e += y * y;
        return e;
    };
    const double plain = lowEnergy(play(rip(0.2, 3.0, 0.01), 48000)), thump = lowEnergy(play(hit, 48000));
    EXPECT_GT(thump, 10 * plain) << "low-passed energy: rip " << plain << ", ball hit " << thump;
}

TEST(WavFile, FloatSamplesRoundTripBitForBit) {
    const std::string path = (std::filesystem::temp_directory_path() / "clothtear_wav_roundtrip.wav").string();
    const std::vector<float> s = play(rip(0.2, 1.0, 0.01), 4800);
    ASSERT_EQ(writeWav(path, s, 2, 48000), "");
    const WavData w = readWav(path);
    ASSERT_EQ(w.error, "");
    EXPECT_EQ(w.channels, 2);
    EXPECT_EQ(w.sampleRate, 48000);
    EXPECT_EQ(w.frames(), 4800u);
    EXPECT_EQ(w.samples, s);
    EXPECT_EQ(std::filesystem::file_size(path), 12 + 8 + 18 + 8 + 4 + 8 + s.size() * 4);
    std::filesystem::remove(path);
}

namespace {

struct Track {
    std::vector<float> samples;
    std::vector<uint64_t> tearsPerFrame; // tears logged in each frame
    double seconds = 0, tornLength = 0;
    double strainSquaredLength = 0; // m: sum of strain^2 x rest length over the tears (energy density x length / (k/2))
};

// With secondBallFrame >= 0, a copy of the scene's ball is thrown again at that frame, 1.5 m to the
// side of the first (a second burst of tears that does not depend on how the first one trails off).
Track runScene(const std::string& scene, const std::vector<std::string>& sets, int frames, int secondBallFrame = -1) {
    World w;
    EXPECT_EQ(loadScene(w, scene, sets), "");
    const std::vector<Ball> thrown = w.balls;
    Soundtrack sound(w);
    Track t;
    for (int f = 0; f < frames; ++f) {
        if (f == secondBallFrame && !thrown.empty()) {
            Ball again = thrown.front();
            again.x.x() += 1.5f;
            w.balls.push_back(again);
        }
        const uint64_t before = w.tearLog.total();
        w.step();
        sound.afterFrame(w);
        t.tearsPerFrame.push_back(w.tearLog.total() - before);
    }
    for (const TearEvent& e : w.tearLog.events) {
        t.tornLength += e.restLength;
        t.strainSquaredLength += double(e.strain) * double(e.strain) * e.restLength;
    }
    t.samples = sound.samples();
    t.seconds = w.time;
    EXPECT_EQ(sound.frames(), size_t(std::llround(w.time * 48000))) << "the track is as long as the run, to the sample";
    return t;
}

} // namespace

// The envelope follows the tear log: a frame in which tears were logged sounds in that frame or the
// next (a tear's grains start within one frame after it), the sound rises at the start of each burst
// (tears after two frames without: the first, over silence, when ball-r0.5-v3's ball hits at frame
// 13, and the second ball's, thrown at frame 60, besides the first's stragglers), and a frame that
// sounds has tears in the ten frames before it (the longest sound, a ball's thump, lasts 150 ms = 9
// frames): nothing sounds but the tears. With one ball the bursts after the first were its
// stragglers, whose number moves with round-off (1-5 under a 1e-6 change of gravity, over one and two
// threads): the second ball makes a burst that does not.
TEST(Soundtrack, EnvelopeRisesWithinAFrameOfEachBurstOfTears) {
    const Track t = runScene("ball-r0.5-v3", {}, 100, 60);
    const std::vector<double> rms = frameRms(t.samples);
    ASSERT_EQ(rms.size(), t.tearsPerFrame.size());
    int tearFrames = 0, bursts = 0;
    bool secondBall = false; // a burst from frame 60 on
    for (size_t f = 0; f < rms.size(); ++f) {
        const double next = f + 1 < rms.size() ? rms[f + 1] : 0.0;
        if (t.tearsPerFrame[f]) {
            ++tearFrames;
            EXPECT_GT(std::max(rms[f], next), 0.0) << "frame " << f << ": " << t.tearsPerFrame[f] << " tears, silent";
            // A burst: tears after two frames without (the grains of earlier tears are over by then).
            const bool burst = f >= 2 && t.tearsPerFrame[f - 1] == 0 && t.tearsPerFrame[f - 2] == 0;
            if (burst) {
                ++bursts;
                secondBall |= f >= 60;
                EXPECT_GT(std::max(rms[f], next), rms[f - 1]) << "frame " << f << ": a burst of tears that does not rise";
            }
        }
        if (rms[f] > 0) {
            bool tearBefore = false;
            for (size_t g = f >= 10 ? f - 10 : 0; g <= f; ++g) tearBefore |= t.tearsPerFrame[g] != 0;
            EXPECT_TRUE(tearBefore) << "frame " << f << " sounds (RMS " << rms[f] << ") with no tear before it";
        }
    }
    EXPECT_GT(tearFrames, 3) << "the ball is meant to tear";
    EXPECT_GE(bursts, 2);
    EXPECT_TRUE(secondBall) << "the second ball's tears are a burst of their own";
}

// A run with no tears is exactly silent, even with a ball pressing into the cloth.
TEST(Soundtrack, NoTearsNoSound) {
    const Track t = runScene("ball-r0.5-v3", {"tear.enabled=0"}, 60);
    EXPECT_EQ(t.tornLength, 0.0);
    EXPECT_EQ(sumSquares(t.samples), 0.0);
}

// Issue 15: the same rip at two resolutions is about as loud. The pull scene (straight down) tears
// the same rip at 40 and 80 a side (TearScenes.PullRipIsTheSameAtTwoResolutions: its length in metres
// within 25 %); at 80 it takes more tears of springs half as long. Measured (4 s): at 40, 20 tears,
// 3.14 m of springs torn, sound energy 330; at 80, 32 tears, 2.46 m, 321: a ratio of 0.97 (-0.1 dB)
// where the torn length's is 0.78 and that of sum(strain^2 x length) 0.88 (the finer cloth's tears
// come at a mean strain of 0.237 against 0.221). One grain per tear carrying the spring's own energy
// E (which scales with L^2) would have given about 32/20 x 1/4 = 0.4 (-4 dB).
// Tolerances: the energy within 30 % (about 1.5 dB), since the simulated rips themselves differ by up
// to 25 % in length; and the synthesizer's own part, the energy ratio over the ratio of what it is
// built to follow (energy density x length, i.e. sum(strain^2 x length)), within 15 % (what is
// left: the tear speed's effect on grain overlap).
// Now (2026-11-28) the rips differ more: at 40, 18 tears, 3.22 m torn, energy 422; at 80, 29 tears,
// 2.30 m, 308, a ratio of 0.73 on two threads (0.71 on four; on one, 27 tears at 80 and 0.69, 1 %
// outside the tolerance): the simulation's part (sum(strain^2 x length): 0.69 on two threads) is
// issue 13 goal 1's open rip length, not the synthesizer's (its part is 1.05). The runs take two
// threads, so that every machine checks the same ones (the state depends on the thread count).
TEST(Soundtrack, TheSameSceneAtTwoResolutionsIsAboutAsLoud) {
    const test::OmpThreads twoThreads(2);
    double energy[2], torn[2], followed[2];
    size_t tears[2];
    const int res[2] = {40, 80};
    for (int k = 0; k < 2; ++k) {
        const std::string r = std::to_string(res[k]);
        const Track t = runScene("pull", {"pull.angle=0", "cloth.resolution_x=" + r, "cloth.resolution_y=" + r}, 240);
        energy[k] = sumSquares(t.samples);
        torn[k] = t.tornLength;
        followed[k] = t.strainSquaredLength;
        tears[k] = 0;
        for (uint64_t n : t.tearsPerFrame) tears[k] += n;
        std::cout << "pull at " << r << ": " << tears[k] << " tears, " << torn[k] << " m of springs torn, sum(strain^2 x length) "
                  << followed[k] << " m, sound energy " << energy[k] << " (sum of squares)\n";
    }
    ASSERT_GT(energy[0], 0.0);
    EXPECT_GT(double(tears[1]) / double(tears[0]), 1.3) << "the finer cloth tears more springs";
    const double ratio = energy[1] / energy[0], tornRatio = torn[1] / torn[0];
    const double followedRatio = followed[1] / followed[0];
    EXPECT_NEAR(ratio, 1.0, 0.3) << "sound energy at 80 / at 40";
    EXPECT_NEAR(ratio / followedRatio, 1.0, 0.15)
        << "energy ratio " << ratio << ", sum(strain^2 x length) ratio " << followedRatio << ", torn-length ratio "
        << tornRatio;
}

namespace {
// Zero crossings per second of the left channel where it sounds: a brightness measure (a band of
// noise around f crosses zero about 2 f times a second).
double crossingsPerSecond(const std::vector<float>& stereo) {
    size_t crossings = 0, sounding = 0;
    float last = 0.f;
    for (size_t i = 0; i < stereo.size(); i += 2) {
        const float x = stereo[i];
        if (x == 0.f) continue;
        ++sounding;
        if (last != 0.f && (x > 0.f) != (last > 0.f)) ++crossings;
        last = x;
    }
    return sounding ? double(crossings) * 48000.0 / double(sounding) : 0.0;
}
} // namespace

// Issue 15: a knife cut has its own character. Across the hanging curtain (slack: its springs
// release next to no energy) it still sounds, within the frame of the cut, and it is brighter than
// a rip: its zero crossings per second are more than one and a half times those of the pull
// scene's rip (an 8 kHz snip against a rip's 1-4 kHz). At 40 and 80 a side the knife is about as
// loud (the grains follow the length cut, not the springs).
TEST(Soundtrack, AKnifeCutSoundsThroughSlackClothAndSnipsBrighterThanARip) {
    double energy[2] = {0, 0}, bright = 0;
    const int res[2] = {40, 80};
    for (int k = 0; k < 2; ++k) {
        World w;
        const std::string r = std::to_string(res[k]);
        const std::vector<std::string> sets = {"cloth.resolution_x=" + r, "cloth.resolution_y=" + r};
        ASSERT_EQ(loadScene(w, "curtain", sets), "");
        for (int f = 0; f < 30; ++f) w.step();
        Soundtrack sound(w);
        ASSERT_GT(w.cut({Vec2d(-1.2, 0.0), Vec2d(1.2, 0.0)}).springsCut, 0u);
        for (int f = 0; f < 20; ++f) {
            w.step();
            sound.afterFrame(w);
        }
        EXPECT_GT(w.tearLog.counts[int(TearMode::Knife)], 0u);
        const std::vector<float>& s = sound.samples();
        const size_t frame = 2 * kFrame; // the first frame
        double first = 0;
        for (size_t i = 0; i < frame && i < s.size(); ++i) first += double(s[i]) * s[i];
        EXPECT_GT(first, 0.0) << res[k] << ": the cut sounds in its frame";
        energy[k] = sumSquares(s);
        if (k == 0) bright = crossingsPerSecond(s);
        std::cout << "knife at " << r << ": " << w.tearLog.counts[int(TearMode::Knife)] << " springs cut, sound energy "
                  << energy[k] << ", " << crossingsPerSecond(s) << " zero crossings per second\n";
    }
    EXPECT_NEAR(energy[1] / energy[0], 1.0, 0.3);
    const Track rip = runScene("pull", {"pull.angle=0", "cloth.resolution_x=40", "cloth.resolution_y=40"}, 240);
    const double ripBright = crossingsPerSecond(rip.samples);
    std::cout << "rip (pull at 40): " << ripBright << " zero crossings per second\n";
    EXPECT_GT(bright, 1.5 * ripBright);
}

