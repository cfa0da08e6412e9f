// --audio-out through the binary: the WAV's length, silence without tears, identical bytes on a
// second run, the report's fields, and an unwritable path refused before the run.
#include "cli_harness.h"
#include "wav_file.h"

#include <nlohmann/json.hpp>

#include <cmath>

using namespace clitest;

TEST_F(CliTest, AudioOutIsAsLongAsTheRunToTheSampleAndReported) {
    const std::string wav = (dir / "rip.wav").string();
    const RunResult r = run("--headless --scene ball-r0.5-v3 --seconds 1.5 --audio-out '" + wav + "' --json -");
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json report = nlohmann::json::parse(r.out);
    const clothtear::audio::WavData w = clothtear::audio::readWav(wav);
    ASSERT_EQ(w.error, "");
    EXPECT_EQ(w.channels, 2);
    EXPECT_EQ(w.sampleRate, 48000);
    const double seconds = report["seconds"].get<double>(); // 90 frames of the float 1/60 s
    EXPECT_EQ(w.frames(), size_t(std::llround(seconds * 48000)));
    EXPECT_EQ(w.frames(), 72000u);
    EXPECT_EQ(report["audio"]["file"], wav);
    EXPECT_EQ(report["audio"]["samples"], 72000);
    EXPECT_DOUBLE_EQ(report["audio"]["seconds"].get<double>(), 1.5);
    EXPECT_GT(report["tears_total"].get<int>(), 0);
    EXPECT_GT(report["audio"]["grains"].get<int>(), 0);
    double energy = 0;
    for (float x : w.samples) energy += double(x) * x;
    EXPECT_GT(energy, 0.0) << "the ball tears the cloth: the track is not silent";
}

TEST_F(CliTest, AudioOutOfARunWithoutTearsIsExactlySilent) {
    const std::string wav = (dir / "quiet.wav").string();
    const RunResult r = run("--headless --scene tension --seconds 0.5 --set tear.enabled=0 --audio-out '" + wav + "' --json -");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["tears_total"], 0);
    const clothtear::audio::WavData w = clothtear::audio::readWav(wav);
    ASSERT_EQ(w.error, "");
    EXPECT_EQ(w.frames(), 24000u);
    for (float x : w.samples) ASSERT_EQ(x, 0.f);
}

TEST_F(CliTest, AudioOutIsTheSameBytesOnASecondRun) {
    const std::string a = (dir / "a.wav").string(), b = (dir / "b.wav").string();
    const std::string args = "--headless --scene ball-r0.5-v3 --seconds 1 --audio-out ";
    ASSERT_EQ(run(args + "'" + a + "'").status, 0);
    const RunResult second = run(args + "'" + b + "'");
    ASSERT_EQ(second.status, 0);
    EXPECT_NE(second.out.find("audio " + b + " (1 s)"), std::string::npos) << second.out;
    const std::string bytesA = slurp(a), bytesB = slurp(b);
    EXPECT_EQ(bytesA.size(), 44u + 14u + 48000u * 8u);
    EXPECT_TRUE(bytesA == bytesB) << "two runs of the same scene wrote different soundtracks";
}

TEST_F(CliTest, AudioOutToAPathThatCannotBeWrittenIsRefusedBeforeTheRun) {
    const std::string bad = "--headless --seconds 30 --audio-out '" + (dir / "no/such/dir/x.wav").string() + "'";
    expectRefused(run(bad), bad, {"--audio-out: cannot write", "x.wav"});
}
