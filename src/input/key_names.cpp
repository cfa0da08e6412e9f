// Key and mouse-button names for input scripts. The numbers are GLFW's key codes (GLFW/glfw3.h);
// app_window.cpp checks a few of them against the real header with static_assert.
#include "input_script.h"

#include <charconv>
#include <cstring>

namespace clothtear::app {
namespace {

struct NamedKey {
    const char* name;
    int code;
};

const NamedKey kNamedKeys[] = {
    {"SPACE", 32},       {"APOSTROPHE", 39},    {"COMMA", 44},        {"MINUS", 45},         {"PERIOD", 46},
    {"SLASH", 47},       {"SEMICOLON", 59},     {"EQUAL", 61},        {"LEFT_BRACKET", 91},  {"BACKSLASH", 92},
    {"RIGHT_BRACKET", 93}, {"GRAVE_ACCENT", 96}, {"ESCAPE", 256},     {"ENTER", 257},        {"TAB", 258},
    {"BACKSPACE", 259},  {"INSERT", 260},       {"DELETE", 261},      {"RIGHT", 262},        {"LEFT", 263},
    {"DOWN", 264},       {"UP", 265},           {"PAGE_UP", 266},     {"PAGE_DOWN", 267},    {"HOME", 268},
    {"END", 269},        {"KP_ENTER", 335},     {"LEFT_SHIFT", 340},  {"LEFT_CONTROL", 341}, {"LEFT_ALT", 342},
    {"LEFT_SUPER", 343}, {"RIGHT_SHIFT", 344},  {"RIGHT_CONTROL", 345}, {"RIGHT_ALT", 346},  {"RIGHT_SUPER", 347},
};

constexpr int kF1 = 290; // F1..F25 are consecutive

} // namespace

std::string keyName(int code) {
    if ((code >= 'A' && code <= 'Z') || (code >= '0' && code <= '9')) return std::string(1, char(code));
    if (code >= kF1 && code < kF1 + 25) return std::string("F").append(std::to_string(code - kF1 + 1));
    for (const NamedKey& k : kNamedKeys)
        if (k.code == code) return k.name;
    return std::string("KEY_").append(std::to_string(code));
}

int keyFromName(std::string_view name) {
    if (name.size() == 1) {
        const char c = name[0];
        if (c >= 'a' && c <= 'z') return c - 'a' + 'A';
        if ((c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9')) return c;
    }
    auto number = [](std::string_view digits, int& out) {
        const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), out);
        return ec == std::errc() && ptr == digits.data() + digits.size() && !digits.empty();
    };
    int n = 0;
    if (name.size() >= 2 && (name[0] == 'F' || name[0] == 'f') && number(name.substr(1), n) && n >= 1 && n <= 25)
        return kF1 + n - 1;
    if (name.starts_with("KEY_") && number(name.substr(4), n) && n >= 0 && n < 512) return n;
    for (const NamedKey& k : kNamedKeys)
        if (name == k.name) return k.code;
    return -1;
}

const char* buttonName(int button) {
    switch (button) {
    case 0: return "left";
    case 1: return "right";
    case 2: return "middle";
    default: return "?";
    }
}

int buttonFromName(std::string_view name) {
    if (name == "left") return 0;
    if (name == "right") return 1;
    if (name == "middle") return 2;
    return -1;
}

} // namespace clothtear::app
