// The default cloth texture, made by the project: a woven fabric of 8 x 8 coloured, numbered patches, so
// that a torn or stretched cloth visibly keeps its texture (each number stays whole on its patch).
// Pure (no GL): tools/make_fabric.cpp writes it to a PNG at build time; the app falls back to it in
// memory when the PNG cannot be read.
#pragma once
#include <cstdint>
#include <vector>

namespace clothtear::app {

struct Image {
    int width = 0, height = 0;
    std::vector<uint8_t> rgba; // row 0 is the top row (as in a PNG)
};

Image makeFabricTexture(int size = 1024, int cells = 8);

} // namespace clothtear::app
