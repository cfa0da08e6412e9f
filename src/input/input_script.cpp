// Input script parsing and writing (format in input_script.h).
#include "input_script.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace clothtear::app {
namespace {

std::vector<std::string_view> splitWords(std::string_view line) {
    std::vector<std::string_view> words;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        size_t j = i;
        while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') ++j;
        if (j > i) words.push_back(line.substr(i, j - i));
        i = j;
    }
    return words;
}

template <class T> bool parseNumber(std::string_view s, T& out) {
    const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && ptr == s.data() + s.size();
}

std::string formatFloat(float v) {
    // Window coordinates and wheel steps: short, exact enough, and round-trips through parseNumber.
    char buf[32];
    const auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return ec == std::errc() ? std::string(buf, ptr) : "0";
}

} // namespace

Result<InputScript> parseInputScript(std::string_view text, const std::string& source) {
    InputScript script;
    int lineNo = 0;
    uint64_t lastFrame = 0;
    bool ended = false;
    size_t pos = 0;
    while (pos <= text.size()) {
        size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(pos, end - pos);
        pos = end + 1;
        ++lineNo;
        if (const size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
        const std::vector<std::string_view> w = splitWords(line);
        if (w.empty()) {
            if (end == text.size()) break;
            continue;
        }
        auto fail = [&](const std::string& what) {
            return Result<InputScript>::failure(source + ":" + std::to_string(lineNo) + ": " + what);
        };
        if (ended) return fail("event after 'end'");
        InputEvent e;
        if (!parseNumber(w[0], e.frame)) return fail("expected a frame number, got '" + std::string(w[0]) + "'");
        if (e.frame < lastFrame)
            return fail("frame " + std::to_string(e.frame) + " comes after frame " + std::to_string(lastFrame) +
                        " (frames must not decrease)");
        if (w.size() < 2) return fail("missing event after the frame number");
        const std::string_view verb = w[1];
        auto needArgs = [&](size_t n, const char* usage) -> std::string {
            if (w.size() != n + 2) return std::string("'") + std::string(verb) + "' takes " + usage;
            return {};
        };
        std::vector<InputEvent> add;
        if (verb == "move" || verb == "scroll") {
            if (auto err = needArgs(2, verb == "move" ? "<x> <y>" : "<dx> <dy>"); !err.empty()) return fail(err);
            if (!parseNumber(w[2], e.x) || !parseNumber(w[3], e.y) || !std::isfinite(e.x) || !std::isfinite(e.y))
                return fail("bad number in '" + std::string(w[2]) + " " + std::string(w[3]) + "'");
            e.kind = verb == "move" ? InputKind::Move : InputKind::Scroll;
            add.push_back(e);
        } else if (verb == "down" || verb == "up" || verb == "click") {
            if (auto err = needArgs(1, "a button (left, right, middle)"); !err.empty()) return fail(err);
            e.code = buttonFromName(w[2]);
            if (e.code < 0) return fail("unknown button '" + std::string(w[2]) + "' (left, right, middle)");
            e.kind = verb == "up" ? InputKind::Up : InputKind::Down;
            add.push_back(e);
            if (verb == "click") add.push_back(InputEvent{e.frame, InputKind::Up, 0.f, 0.f, e.code});
        } else if (verb == "key_down" || verb == "key_up" || verb == "key") {
            if (auto err = needArgs(1, "a key name (A, 5, F1, SPACE, ESCAPE, KEY_<code>...)"); !err.empty())
                return fail(err);
            e.code = keyFromName(w[2]);
            if (e.code < 0) return fail("unknown key '" + std::string(w[2]) + "'");
            e.kind = verb == "key_up" ? InputKind::KeyUp : InputKind::KeyDown;
            add.push_back(e);
            if (verb == "key") add.push_back(InputEvent{e.frame, InputKind::KeyUp, 0.f, 0.f, e.code});
        } else if (verb == "char") {
            if (auto err = needArgs(1, "a unicode codepoint number"); !err.empty()) return fail(err);
            if (!parseNumber(w[2], e.code) || e.code <= 0 || e.code > 0x10FFFF)
                return fail("bad codepoint '" + std::string(w[2]) + "'");
            e.kind = InputKind::Char;
            add.push_back(e);
        } else if (verb == "end") {
            if (auto err = needArgs(0, "no arguments"); !err.empty()) return fail(err);
            e.kind = InputKind::End;
            add.push_back(e);
            ended = true;
        } else {
            return fail("unknown event '" + std::string(verb) +
                        "' (move, down, up, click, scroll, key_down, key_up, key, char, end)");
        }
        lastFrame = e.frame;
        script.events.insert(script.events.end(), add.begin(), add.end());
        if (end == text.size()) break;
    }
    return Result<InputScript>{script, {}};
}

Result<InputScript> loadInputScript(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return Result<InputScript>::failure(path + ": cannot open input script");
    std::stringstream buffer;
    buffer << in.rdbuf();
    return parseInputScript(buffer.str(), path);
}

std::string formatInputScript(const InputScript& script) {
    std::string out = "# clothtear input script: <frame> <event> <args> (see src/input/input_script.h)\n";
    for (const InputEvent& e : script.events) {
        out += std::to_string(e.frame) + " ";
        switch (e.kind) {
        case InputKind::Move: out += "move " + formatFloat(e.x) + " " + formatFloat(e.y); break;
        case InputKind::Scroll: out += "scroll " + formatFloat(e.x) + " " + formatFloat(e.y); break;
        case InputKind::Down: out += std::string("down ") + buttonName(e.code); break;
        case InputKind::Up: out += std::string("up ") + buttonName(e.code); break;
        case InputKind::KeyDown: out += "key_down " + keyName(e.code); break;
        case InputKind::KeyUp: out += "key_up " + keyName(e.code); break;
        case InputKind::Char: out += "char " + std::to_string(e.code); break;
        case InputKind::End: out += "end"; break;
        }
        out += "\n";
    }
    return out;
}

} // namespace clothtear::app
