// Input scripts: a recorded session of mouse moves, button presses, wheel turns, keys and text, each
// stamped with the frame it happened in. `--record FILE` writes one while a person plays; `--script FILE`
// replays it, so any session (and every app test) runs without a person.
//
// Format, one event per line ('#' starts a comment; blank lines are ignored):
//   <frame> move <x> <y>          cursor position in window coordinates (pixels, origin top-left)
//   <frame> down <button>         button: left | right | middle
//   <frame> up <button>
//   <frame> click <button>        down and up in the same frame
//   <frame> scroll <dx> <dy>      wheel steps
//   <frame> key_down <KEY>        KEY: A..Z, 0..9, F1..F12, SPACE, ESCAPE, ENTER, ... or KEY_<code>
//   <frame> key_up <KEY>
//   <frame> key <KEY>             key_down and key_up in the same frame
//   <frame> char <codepoint>      one typed character (text fields of the panel)
//   <frame> end                   the replay stops after this frame
// Frames never decrease. Pure (no GL, no GLFW): key codes are GLFW's values, spelled out in key_names.cpp.
#pragma once
#include "clothtear/types.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace clothtear::app {

enum class InputKind { Move, Down, Up, Scroll, KeyDown, KeyUp, Char, End };

struct InputEvent {
    uint64_t frame = 0;
    InputKind kind = InputKind::Move;
    float x = 0.f, y = 0.f; // Move: cursor; Scroll: offsets
    int code = 0;           // Down/Up: button (0 left, 1 right, 2 middle); KeyDown/KeyUp: key; Char: codepoint
    bool operator==(const InputEvent&) const = default;
};

struct InputScript {
    std::vector<InputEvent> events; // in frame order
    // The frame after which a replay stops: the `end` line, else the last event's frame.
    uint64_t lastFrame() const { return events.empty() ? 0 : events.back().frame; }
};

// Parses script text; errors read "<source>:<line>: <what>".
Result<InputScript> parseInputScript(std::string_view text, const std::string& source);
// Reads and parses a file; a missing file is an error naming it.
Result<InputScript> loadInputScript(const std::string& path);
// The text form, one event per line (click/key shorthands are written as their two events).
std::string formatInputScript(const InputScript& script);

// Key names <-> GLFW key codes. Unknown codes are named KEY_<code>; keyFromName returns -1 when unknown.
std::string keyName(int code);
int keyFromName(std::string_view name);
const char* buttonName(int button);
int buttonFromName(std::string_view name); // -1 when unknown

} // namespace clothtear::app
