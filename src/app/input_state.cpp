// Applying input events to the per-frame input state.
#include "input_state.h"

namespace clothtear::app {

void InputState::apply(const InputEvent& e) {
    switch (e.kind) {
    case InputKind::Move:
        mouseX = e.x;
        mouseY = e.y;
        break;
    case InputKind::Down:
        if (e.code >= 0 && e.code < 3) buttons[e.code] = true, pressedLatch[e.code] = true;
        break;
    case InputKind::Up:
        if (e.code >= 0 && e.code < 3) buttons[e.code] = false;
        break;
    case InputKind::Scroll:
        wheelX += e.x;
        wheelY += e.y;
        break;
    case InputKind::KeyDown:
        if (e.code >= 0 && e.code < 512) keys[e.code] = true, keyLatch[e.code] = true;
        break;
    case InputKind::KeyUp:
        if (e.code >= 0 && e.code < 512) keys[e.code] = false;
        break;
    case InputKind::Char:
        chars.push_back(unsigned(e.code));
        break;
    case InputKind::End:
        break;
    }
    pending.push_back(e);
}

void InputState::endFrame() {
    pressedLatch = {};
    keyLatch = {};
    wheelX = wheelY = 0.f;
    chars.clear();
    pending.clear();
}

} // namespace clothtear::app
