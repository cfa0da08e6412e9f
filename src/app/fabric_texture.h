// The cloth textures the project makes itself. Pure (no GL): tools/make_fabric.cpp writes both to PNGs at
// build time (woven.png, numbered.png); the app falls back to these functions in memory when a PNG
// cannot be read.
//  - makeWovenTexture: the default, a woven fabric (a 2/2 twill check of two colours, every thread drawn)
//    that tiles seamlessly, so it looks like cloth on the curtain and stays whole when UVs wrap.
//  - makeFabricTexture: the debug texture, 8 x 8 coloured, numbered patches, so that a torn or stretched
//    cloth visibly keeps its texture (each number stays whole on its patch, Önal 3.3).
#pragma once
#include <cstdint>
#include <vector>

namespace clothtear::app {

struct Image {
    int width = 0, height = 0;
    std::vector<uint8_t> rgba; // row 0 is the top row (as in a PNG)
};

// The colour repeat of the woven check, in threads (each colour a stripe of half of it, in warp and weft).
inline constexpr int kWovenRepeat = 16;
// Threads across the default woven texture: 96 over 1024 px is a thread every 10.7 px, about 4.5 px on
// the screen for the whole 2 m curtain at 1280 x 720: the threads and the twill show, without moire, and
// the check (6 repeats across) reads as a check. 64 made each twill float a coarse dash at that distance.
inline constexpr int kWovenThreads = 96;

// A size x size woven fabric of `threads` warp threads across and as many weft threads down, so a thread
// is size / threads px wide. `threads` is rounded to a whole number of colour repeats (kWovenRepeat, at
// least one) so that the right column continues into the left one and the bottom row into the top one.
// Deterministic: the per-thread variation comes from a hash of the thread's index, not from rand().
Image makeWovenTexture(int size = 1024, int threads = kWovenThreads);

// The numbered debug fabric: cells x cells patches, numbered from 1 at the top left.
Image makeFabricTexture(int size = 1024, int cells = 8);

} // namespace clothtear::app
