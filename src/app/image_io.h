// Reading and writing images with stb (implementations come from Debian's libstb). Pure (no GL).
#pragma once
#include "clothtear/types.h"
#include "fabric_texture.h"

#include <string>

namespace clothtear::app {

// Loads a PNG/JPG/... as RGBA, row 0 at the top. The error names the file and stb's reason.
Result<Image> loadImage(const std::string& path);
// Writes RGBA rows (row 0 at the top) as PNG. Returns "" or a message.
std::string savePng(const std::string& path, const Image& image);

} // namespace clothtear::app
