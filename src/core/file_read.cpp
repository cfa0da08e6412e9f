// readWholeFile (file_read.h): the checks before reading, then the bytes.
#include "file_read.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>

namespace clothtear {

std::string readWholeFile(const std::string& path, std::string& bytes, const FileLimits& limits) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (ec || !fs::exists(status))
        return path + ": cannot open: " + (ec ? ec.message() : std::string("No such file or directory"));
    if (fs::is_directory(status))
        return path + ": cannot read: is a directory, not " + std::string(limits.kind);
    if (!fs::is_regular_file(status))
        return path + ": cannot read: not a regular file";
    // Refused before reading: a loader's arrays take a few times the file's size.
    if (const uintmax_t size = fs::file_size(path, ec); !ec && size > limits.maxBytes)
        return path + ": file is " + std::to_string(size >> 20) + " MiB; " + limits.maxText;
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return path + ": cannot open: " + (errno ? std::strerror(errno) : "unknown error");
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (in.bad())
        return path + ": read error";
    return {};
}

} // namespace clothtear
