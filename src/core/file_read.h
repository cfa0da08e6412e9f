// Reading a whole input file with the checks every loader of the core wants first (OBJ meshes, world
// files): it exists, is a regular file (a directory or a FIFO is named, never opened, so nothing
// blocks) and is not larger than the loader takes, refused before a byte is read.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>

namespace clothtear {

struct FileLimits {
    uintmax_t maxBytes;       // larger files are refused before reading
    std::string_view kind;    // "an OBJ file": "PATH: cannot read: is a directory, not <kind>"
    std::string maxText;      // after "PATH: file is N MiB; ", e.g. "the importer reads at most 256 MiB"
};

// Reads `path` into `bytes`. Returns "" or one line starting with the path.
std::string readWholeFile(const std::string& path, std::string& bytes, const FileLimits& limits);

} // namespace clothtear
