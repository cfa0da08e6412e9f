// The live input of one frame, fed alike by GLFW callbacks and by a replayed script, so the app (and
// the ImGui panel) cannot tell a person from a replay. Pure: no GL, no GLFW.
#pragma once
#include "input_script.h"

#include <array>
#include <vector>

namespace clothtear::app {

struct InputState {
    float mouseX = 0.f, mouseY = 0.f;     // window coordinates
    std::array<bool, 3> buttons{};        // held now
    std::array<bool, 3> pressedLatch{};   // pressed at some point this frame (a click shorter than a frame)
    float wheelX = 0.f, wheelY = 0.f;     // steps accumulated this frame
    std::array<bool, 512> keys{};         // held now, by GLFW key code
    std::array<bool, 512> keyLatch{};     // pressed at some point this frame
    std::vector<unsigned> chars;          // typed this frame
    std::vector<InputEvent> pending;      // this frame's events, in order, for the tools and hotkeys

    void apply(const InputEvent& e);
    bool keyHeld(int code) const { return code >= 0 && code < 512 && (keys[code] || keyLatch[code]); }
    bool buttonHeld(int b) const { return b >= 0 && b < 3 && (buttons[b] || pressedLatch[b]); }
    void endFrame(); // clears the per-frame parts
};

} // namespace clothtear::app
