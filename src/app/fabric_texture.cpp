// The project's cloth textures, procedural.
//   [WOVEN]     the default: a 2/2 twill check of two colours, every thread shaded
//   [NUMBERED]  the debug texture: pastel patches in a checker of hues, a twill weave, seams between
//               patches, and the patch number (1 = top-left) printed large with stb_easy_font
#include "fabric_texture.h"

#include <algorithm>
#include <cmath>
#include <string>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb_easy_font.h>
#pragma GCC diagnostic pop

namespace clothtear::app {
namespace {

struct Rgb {
    float r, g, b;
};

Rgb hsv(float h, float s, float v) {
    h = std::fmod(h, 1.f) * 6.f;
    const int i = int(h);
    const float f = h - float(i), p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
    switch (i % 6) {
    case 0: return {v, t, p};
    case 1: return {q, v, p};
    case 2: return {p, v, t};
    case 3: return {p, q, v};
    case 4: return {t, p, v};
    default: return {v, p, q};
    }
}

void put(Image& img, int x, int y, Rgb c) {
    if (x < 0 || y < 0 || x >= img.width || y >= img.height) return;
    uint8_t* px = &img.rgba[(size_t(y) * img.width + x) * 4];
    px[0] = uint8_t(std::clamp(c.r, 0.f, 1.f) * 255.f + 0.5f);
    px[1] = uint8_t(std::clamp(c.g, 0.f, 1.f) * 255.f + 0.5f);
    px[2] = uint8_t(std::clamp(c.b, 0.f, 1.f) * 255.f + 0.5f);
    px[3] = 255;
}

// Prints text centred on (cx, cy), each font pixel drawn as a scale x scale block.
void printText(Image& img, const std::string& text, float cx, float cy, float scale, Rgb color) {
    static char buffer[64 * 1024];
    std::string t = text;
    const float w = float(stb_easy_font_width(t.data())) * scale;
    const float h = 7.f * scale; // digits are 7 font pixels tall
    const int quads = stb_easy_font_print(0, 0, t.data(), nullptr, buffer, sizeof buffer);
    const float ox = cx - 0.5f * w, oy = cy - 0.5f * h;
    for (int q = 0; q < quads; ++q) {
        const float* v = reinterpret_cast<const float*>(buffer + q * 64); // 4 vertices of 16 bytes
        const float x0 = v[0], y0 = v[1], x1 = v[8], y1 = v[9];       // corners 0 and 2
        for (int y = int(std::floor(oy + y0 * scale)); y < int(std::floor(oy + y1 * scale)); ++y)
            for (int x = int(std::floor(ox + x0 * scale)); x < int(std::floor(ox + x1 * scale)); ++x)
                put(img, x, y, color);
    }
}

} // namespace

// ============================================================================================ [WOVEN]

namespace {

// A 32-bit integer hash (lowbias32, C. Wellons): the fixed "random" variation of each thread.
uint32_t hash32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

// A value in [0, 1) for the pair (a, b).
float hash01(uint32_t a, uint32_t b) { return float(hash32(hash32(a) ^ (b * 0x9e3779b9U)) >> 8) / 16777216.f; }

float smoothstep(float e0, float e1, float x) {
    const float t = std::clamp((x - e0) / (e1 - e0), 0.f, 1.f);
    return t * t * (3.f - 2.f * t);
}

int wrap(int i, int n) { return ((i % n) + n) % n; }

// Slub: the yarn's thickness, so its brightness, drifts slowly along the thread. Value noise with a knot
// every 2 thread widths, periodic over `period` knots (the texture's height or width in knots).
float slub(uint32_t thread, float along, int period) {
    const float t = along * 0.5f, f = std::floor(t);
    const int k = wrap(int(f), period);
    const float u = smoothstep(0.f, 1.f, t - f);
    return hash01(thread, uint32_t(k)) * (1.f - u) + hash01(thread, uint32_t((k + 1) % period)) * u;
}

struct Weave {
    int threads = kWovenThreads; // warp threads across = weft threads down, a multiple of kWovenRepeat
    Rgb colors[2] = {{0.66f, 0.10f, 0.10f},   // deep red
                     {0.10f, 0.13f, 0.28f}};  // navy
    std::vector<Rgb> warp, weft;              // each thread's own colour (stripe colour, varied)

    explicit Weave(int n) : threads(n) {
        for (int pass = 0; pass < 2; ++pass) {
            std::vector<Rgb>& out = pass == 0 ? warp : weft;
            for (int i = 0; i < n; ++i) {
                // Stripes of half a repeat each; the same order in warp and weft makes a square check.
                const Rgb c = colors[(i % kWovenRepeat) < kWovenRepeat / 2 ? 0 : 1];
                // Each thread a little lighter or darker and a little off in hue (dye lots differ).
                const uint32_t id = uint32_t(pass * n + i);
                const float tone = 0.88f + 0.24f * hash01(id, 7);
                out.push_back({c.r * tone * (0.96f + 0.08f * hash01(id, 1)), c.g * tone * (0.96f + 0.08f * hash01(id, 2)),
                               c.b * tone * (0.96f + 0.08f * hash01(id, 3))});
            }
        }
    }

    // The colour at (tu, tv), in thread widths: warp thread i = floor(tu) runs down, weft thread
    // j = floor(tv) across. 2/2 twill: warp i lies over weft j when (i - j) mod 4 < 2, so every thread
    // floats over two crossing threads and dives under the next two, and the floats step one thread per
    // row (the twill diagonal):
    //
    //      i:  0 1 2 3                 | = warp on top, - = weft on top
    //   j=0    | | - -
    //   j=1    - | | -
    //   j=2    - - | |
    //   j=3    | - - |
    Rgb at(float tu, float tv) const {
        const int i = wrap(int(std::floor(tu)), threads), j = wrap(int(std::floor(tv)), threads);
        const float fu = tu - std::floor(tu), fv = tv - std::floor(tv);
        const int w = wrap(i - j, 4);
        const bool warpOver = w < 2;
        // The thread on top: `across` its width in [0, 1], `along` its float in [0, 2] (0 where it comes
        // up from under the crossing thread, 2 where it dives again).
        const float across = warpOver ? fu : fv;
        const float along = warpOver ? float(1 - w) + fv : float(w - 2) + fu;
        const Rgb top = warpOver ? warp[size_t(i)] : weft[size_t(j)];
        const Rgb below = warpOver ? weft[size_t(j)] : warp[size_t(i)];
        const uint32_t id = warpOver ? uint32_t(i) : uint32_t(threads + j);

        // Near the ends of its float the thread bends down under its neighbour: darker and narrower.
        const float rise = smoothstep(0.f, 0.55f, std::min(along, 2.f - along));
        const float halfWidth = 0.47f * (0.85f + 0.15f * rise);
        const float c = (across - 0.5f) / halfWidth;
        if (std::abs(c) >= 1.f) // the gap between two threads: the crossing thread below, in shadow
            return {below.r * 0.45f, below.g * 0.45f, below.b * 0.45f};
        const float round = std::sqrt(1.f - c * c); // a round yarn, lit from the front
        float shade = (0.6f + 0.4f * round) * (0.72f + 0.28f * rise);
        // Twist: the plies of the yarn show as faint slanted bands, three per thread width along it.
        shade *= 0.94f + 0.06f * std::sin(6.2831853f * (3.f * along + 1.2f * across));
        // Slub along the thread (periodic over the texture: threads / 2 knots).
        shade *= 0.9f + 0.2f * slub(id, warpOver ? tv : tu, threads / 2);
        const float sheen = 0.05f * std::pow(round, 6.f) * rise; // a soft highlight on the crown of the yarn
        return {top.r * shade + sheen, top.g * shade + sheen, top.b * shade + sheen};
    }
};

} // namespace

Image makeWovenTexture(int size, int threads) {
    threads = std::max(kWovenRepeat, (threads + kWovenRepeat / 2) / kWovenRepeat * kWovenRepeat);
    const Weave weave(threads);
    Image img;
    img.width = img.height = size;
    img.rgba.assign(size_t(size) * size * 4, 255);
    // 3 x 3 samples a pixel: the thread edges are smooth, and the PNG does not alias at any size.
    constexpr int kSamples = 3;
    const float toThreads = float(threads) / float(size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            Rgb sum{0.f, 0.f, 0.f};
            for (int sy = 0; sy < kSamples; ++sy)
                for (int sx = 0; sx < kSamples; ++sx) {
                    const Rgb c = weave.at((float(x) + (float(sx) + 0.5f) / kSamples) * toThreads,
                                           (float(y) + (float(sy) + 0.5f) / kSamples) * toThreads);
                    sum = {sum.r + c.r, sum.g + c.g, sum.b + c.b};
                }
            constexpr float kInv = 1.f / float(kSamples * kSamples);
            put(img, x, y, {sum.r * kInv, sum.g * kInv, sum.b * kInv});
        }
    return img;
}

// ========================================================================================= [NUMBERED]

Image makeFabricTexture(int size, int cells) {
    Image img;
    img.width = img.height = size;
    img.rgba.assign(size_t(size) * size * 4, 255);
    const int cell = size / cells;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const int cx = std::min(x / cell, cells - 1), cy = std::min(y / cell, cells - 1);
            // Neighbouring patches differ in hue; the checker alternates lighter and deeper shades.
            const float hue = float((cx * 3 + cy * 5) % cells) / float(cells) + 0.04f;
            const bool light = (cx + cy) % 2 == 0;
            Rgb c = hsv(hue, light ? 0.28f : 0.45f, light ? 0.97f : 0.88f);
            // Twill weave: threads 4 px wide, over-under shifted by one pixel per row.
            const int thread = ((x + y) / 4) % 2;
            const float weave = (thread ? 0.94f : 1.0f) * (0.97f + 0.03f * float(((x / 2) ^ (y / 2)) & 1));
            c = {c.r * weave, c.g * weave, c.b * weave};
            // Seams: a dark line between patches, a faint stitch line through each patch's middle.
            const int lx = x % cell, ly = y % cell;
            if (lx < 3 || ly < 3 || lx >= cell - 3 || ly >= cell - 3) c = {0.18f, 0.16f, 0.2f};
            else if ((lx == cell / 2 || ly == cell / 2) && ((x + y) / 3) % 2 == 0) c = {c.r * 0.8f, c.g * 0.8f, c.b * 0.8f};
            put(img, x, y, c);
        }
    const float scale = float(cell) / 16.f;
    for (int cy = 0; cy < cells; ++cy)
        for (int cx = 0; cx < cells; ++cx) {
            const std::string label = std::to_string(cy * cells + cx + 1);
            const float mx = (cx + 0.5f) * cell, my = (cy + 0.5f) * cell;
            printText(img, label, mx + scale * 0.6f, my + scale * 0.6f, scale, {1.f, 1.f, 1.f}); // light shadow
            printText(img, label, mx, my, scale, {0.12f, 0.1f, 0.16f});
        }
    return img;
}

} // namespace clothtear::app
