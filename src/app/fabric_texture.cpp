// Procedural fabric: pastel patches in a checker of hues, a twill weave, seams between patches, and the
// patch number (1 = top-left) printed large with stb_easy_font.
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
