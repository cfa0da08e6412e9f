// Writes the default cloth texture (src/app/fabric_texture.cpp) to a PNG. Run at build time; the
// committed assets/fabric.png was made by this tool: `clothtear_make_fabric assets/fabric.png`.
#include "fabric_texture.h"

#include <cstdio>
#include <stb_image_write.h>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s OUTPUT.png\n", argv[0]);
        return 2;
    }
    const clothtear::app::Image img = clothtear::app::makeFabricTexture();
    if (!stbi_write_png(argv[1], img.width, img.height, 4, img.rgba.data(), img.width * 4)) {
        std::fprintf(stderr, "%s: cannot write %s\n", argv[0], argv[1]);
        return 1;
    }
    return 0;
}
