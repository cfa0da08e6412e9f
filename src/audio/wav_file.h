// RIFF/WAVE files: 32-bit float writer and a small reader (float or 16-bit PCM) for the tests.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace clothtear::audio {

struct WavData {
    int channels = 0;
    int sampleRate = 0;
    std::vector<float> samples; // interleaved
    std::string error;          // "" when read
    size_t frames() const { return channels ? samples.size() / size_t(channels) : 0; }
};

// Writes interleaved float samples as WAVE_FORMAT_IEEE_FLOAT (fmt of 18 bytes and a fact chunk, as
// the format asks). Returns "" or why not.
std::string writeWav(const std::string& path, const std::vector<float>& interleaved, int channels, int sampleRate);

// Reads a float or 16-bit PCM WAVE file; unknown chunks are skipped.
WavData readWav(const std::string& path);

} // namespace clothtear::audio
