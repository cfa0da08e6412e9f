// RIFF/WAVE (wav_file.h). Little-endian fields, written byte by byte so the host's order does not matter.
#include "wav_file.h"

#include <cstring>
#include <fstream>
#include <iterator>

namespace clothtear::audio {
namespace {

void put(std::string& b, uint32_t v, int bytes) {
    for (int i = 0; i < bytes; ++i) b.push_back(char((v >> (8 * i)) & 0xff));
}
uint32_t get(const std::string& b, size_t at, int bytes) {
    uint32_t v = 0;
    for (int i = 0; i < bytes; ++i) v |= uint32_t(uint8_t(b[at + i])) << (8 * i);
    return v;
}

constexpr int kPcm = 1, kFloat = 3;

} // namespace

std::string writeWav(const std::string& path, const std::vector<float>& interleaved, int channels, int sampleRate) {
    const uint32_t data = uint32_t(interleaved.size() * 4);
    std::string b;
    b += "RIFF";
    put(b, 4 + (8 + 18) + (8 + 4) + (8 + data), 4);
    b += "WAVEfmt ";
    put(b, 18, 4);
    put(b, kFloat, 2);
    put(b, uint32_t(channels), 2);
    put(b, uint32_t(sampleRate), 4);
    put(b, uint32_t(sampleRate * channels * 4), 4); // bytes per second
    put(b, uint32_t(channels * 4), 2);              // block align
    put(b, 32, 2);                                  // bits per sample
    put(b, 0, 2);                                   // no extension
    b += "fact";
    put(b, 4, 4);
    put(b, uint32_t(channels ? interleaved.size() / size_t(channels) : 0), 4);
    b += "data";
    put(b, data, 4);
    for (float f : interleaved) {
        uint32_t bits;
        std::memcpy(&bits, &f, 4);
        put(b, bits, 4);
    }
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) return "cannot write '" + path + "'";
    out.write(b.data(), std::streamsize(b.size()));
    return out ? std::string() : "cannot write '" + path + "'";
}

WavData readWav(const std::string& path) {
    WavData w;
    std::ifstream in(path, std::ios::binary);
    if (!in) return w.error = "cannot open '" + path + "'", w;
    const std::string b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (b.size() < 12 || b.compare(0, 4, "RIFF") != 0 || b.compare(8, 4, "WAVE") != 0)
        return w.error = path + ": not a RIFF/WAVE file", w;
    int format = 0, bits = 0;
    for (size_t at = 12; at + 8 <= b.size();) {
        const std::string id = b.substr(at, 4);
        const size_t size = get(b, at + 4, 4), body = at + 8;
        if (body + size > b.size()) return w.error = path + ": chunk '" + id + "' runs past the end", w;
        if (id == "fmt " && size >= 16) {
            format = int(get(b, body, 2));
            w.channels = int(get(b, body + 2, 2));
            w.sampleRate = int(get(b, body + 4, 4));
            bits = int(get(b, body + 14, 2));
        } else if (id == "data") {
            if (format == kFloat && bits == 32) {
                w.samples.resize(size / 4);
                for (size_t k = 0; k < w.samples.size(); ++k) {
                    const uint32_t v = get(b, body + 4 * k, 4);
                    std::memcpy(&w.samples[k], &v, 4);
                }
            } else if (format == kPcm && bits == 16) {
                w.samples.resize(size / 2);
                for (size_t k = 0; k < w.samples.size(); ++k)
                    w.samples[k] = float(int16_t(get(b, body + 2 * k, 2))) / 32768.f;
            } else {
                return w.error = path + ": only 32-bit float and 16-bit PCM are read", w;
            }
            return w;
        }
        at = body + size + (size & 1); // chunks are padded to an even size
    }
    return w.error = path + ": no data chunk", w;
}

} // namespace clothtear::audio
