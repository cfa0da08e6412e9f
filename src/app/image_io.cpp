// stb_image / stb_image_write wrappers. No STB_*_IMPLEMENTATION here: libstb.so has them.
#include "image_io.h"

#include <cstring>
#include <filesystem>
#include <stb_image.h>
#include <stb_image_write.h>

namespace clothtear::app {

Result<Image> loadImage(const std::string& path) {
    if (path.empty()) return Result<Image>::failure("no file name given");
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return Result<Image>::failure(path + ": no such file");
    int w = 0, h = 0, channels = 0;
    stbi_set_flip_vertically_on_load(0);
    unsigned char* data = stbi_load(path.c_str(), &w, &h, &channels, 4);
    if (!data) {
        const char* why = stbi_failure_reason();
        return Result<Image>::failure(path + ": not a readable image (" + (why ? why : "unknown reason") + ")");
    }
    Image img;
    img.width = w;
    img.height = h;
    img.rgba.assign(data, data + size_t(w) * h * 4);
    stbi_image_free(data);
    if (w < 1 || h < 1 || w > 16384 || h > 16384)
        return Result<Image>::failure(path + ": image size " + std::to_string(w) + "x" + std::to_string(h) +
                                      " is not supported (1..16384)");
    return Result<Image>{std::move(img), {}};
}

std::string savePng(const std::string& path, const Image& image) {
    if (image.width < 1 || image.height < 1) return path + ": empty image";
    if (!stbi_write_png(path.c_str(), image.width, image.height, 4, image.rgba.data(), image.width * 4))
        return path + ": cannot write PNG";
    return {};
}

} // namespace clothtear::app
