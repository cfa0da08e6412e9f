// Config files: `key = value` lines checked against the parameter table (format in config_file.h).
#include "clothtear/config_file.h"

#include "clothtear/params.h"
#include "clothtear/scenes.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace clothtear {
namespace {

// A config is a few dozen lines; anything this large is the wrong file.
constexpr uintmax_t kMaxConfigBytes = uintmax_t(1) << 20;

std::string_view trimmed(std::string_view v) {
    while (!v.empty() && (v.front() == ' ' || v.front() == '\t'))
        v.remove_prefix(1);
    while (!v.empty() && (v.back() == ' ' || v.back() == '\t' || v.back() == '\r'))
        v.remove_suffix(1);
    return v;
}

} // namespace

Result<ConfigFile> parseConfig(std::string_view text, const std::string& source) {
    ConfigFile config;
    Settings probe; // every assignment is applied here once, so a bad one is refused with its line
    size_t lineNo = 0, pos = 0;
    while (pos < text.size()) {
        size_t end = text.find('\n', pos);
        if (end == std::string_view::npos)
            end = text.size();
        std::string_view line = text.substr(pos, end - pos);
        pos = end + 1;
        ++lineNo;
        auto fail = [&](const std::string& what) {
            return Result<ConfigFile>::failure(source + ":" + std::to_string(lineNo) + ": " + what);
        };
        for (size_t i = 0; i < line.size(); ++i) {
            const unsigned char c = static_cast<unsigned char>(line[i]);
            if ((c < 0x20 && c != '\t' && c != '\r') || c == 0x7f) {
                char hex[8];
                std::snprintf(hex, sizeof hex, "0x%02x", c);
                return fail("binary data (byte " + std::string(hex) + " at column " + std::to_string(i + 1) +
                            "), not a text config file");
            }
        }
        line = trimmed(line.substr(0, line.find('#')));
        if (line.empty())
            continue;
        const size_t eq = line.find('=');
        if (eq == std::string_view::npos)
            return fail("expected 'key = value', got '" + shownInMessage(line) + "'");
        const std::string_view key = trimmed(line.substr(0, eq)), value = trimmed(line.substr(eq + 1));
        if (key.empty())
            return fail("missing parameter name before '='");
        if (key == "scene") {
            if (value.empty())
                return fail("scene: empty value");
            if (!parseSceneName(value).ok())
                return fail("unknown scene '" + shownInMessage(value) + "' (see --list-scenes)");
            config.scene = std::string(value);
            continue;
        }
        if (std::string err = setParamFromString(probe, key, value); !err.empty())
            return fail(err);
        config.assignments.push_back(std::string(key) + "=" + std::string(value));
    }
    return Result<ConfigFile>{std::move(config), {}};
}

Result<ConfigFile> loadConfig(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (ec || !fs::exists(status))
        return Result<ConfigFile>::failure(path + ": cannot open config file: No such file or directory");
    if (!fs::is_regular_file(status))
        return Result<ConfigFile>::failure(path + ": cannot read config file: not a regular file");
    if (const uintmax_t size = fs::file_size(path, ec); !ec && size > kMaxConfigBytes)
        return Result<ConfigFile>::failure(path + ": config file is " + std::to_string(size) +
                                           " bytes; a config file has at most 1 MiB");
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return Result<ConfigFile>::failure(
            path + ": cannot open config file: " + (errno ? std::strerror(errno) : "unknown error"));
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.bad())
        return Result<ConfigFile>::failure(path + ": read error");
    return parseConfig(text, path);
}

} // namespace clothtear
