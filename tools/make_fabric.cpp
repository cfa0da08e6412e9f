// Writes the project's cloth textures (src/app/fabric_texture.cpp) as PNGs into a directory:
//   woven.png     the default texture (makeWovenTexture)
//   numbered.png  the debug texture, 64 numbered patches (makeFabricTexture)
// Run at build time into ${build}/assets; the copies committed in assets/ were made by this tool:
// `clothtear_make_fabric assets`.
#include "fabric_texture.h"
#include "image_io.h"

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s OUTPUT_DIR   (writes OUTPUT_DIR/woven.png and OUTPUT_DIR/numbered.png)\n",
                     argv[0]);
        return 2;
    }
    const std::string dir = argv[1];
    const struct {
        const char* name;
        clothtear::app::Image image;
    } textures[] = {{"woven.png", clothtear::app::makeWovenTexture()},
                    {"numbered.png", clothtear::app::makeFabricTexture()}};
    for (const auto& t : textures) {
        const std::string err = clothtear::app::savePng(dir + "/" + t.name, t.image);
        if (!err.empty()) {
            std::fprintf(stderr, "%s: %s\n", argv[0], err.c_str());
            return 1;
        }
    }
    return 0;
}
