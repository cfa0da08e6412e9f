// Input routing. Real GLFW events and replayed script events both become InputEvents applied to one
// InputState; ImGui is fed from that state first, and the app uses the mouse and keyboard only when
// ImGui does not want them (io.WantCaptureMouse / WantCaptureKeyboard).
//
// Section index:
//   [SOURCES]  GLFW callbacks (recorded when --record), script replay (--script)
//   [IMGUI]    feeding ImGui 1.86's io (MousePos, MouseDown, KeysDown, ...)
//   [EVENTS]   buttons, wheel and keys -> tools, camera, hotkeys
//   [HELD]     per-frame work of held input: fly keys, the drag target, the wind source
#include "app.h"

#include "controls.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cmath>

namespace clothtear::app {
namespace {

App* appOf(GLFWwindow* w) { return static_cast<App*>(glfwGetWindowUserPointer(w)); }

} // namespace

// ========================================================================================== [SOURCES]

void App::installCallbacks() {
    glfwSetWindowUserPointer(window_, this);
    glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double x, double y) {
        appOf(w)->onRealEvent(InputEvent{0, InputKind::Move, float(x), float(y), 0});
    });
    glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int button, int action, int) {
        if (button < 0 || button > 2) return;
        appOf(w)->onRealEvent(InputEvent{0, action == GLFW_PRESS ? InputKind::Down : InputKind::Up, 0.f, 0.f, button});
    });
    glfwSetScrollCallback(window_, [](GLFWwindow* w, double dx, double dy) {
        appOf(w)->onRealEvent(InputEvent{0, InputKind::Scroll, float(dx), float(dy), 0});
    });
    glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int) {
        if (action == GLFW_REPEAT || key < 0 || key >= 512) return; // ImGui repeats keys itself
        appOf(w)->onRealEvent(InputEvent{0, action == GLFW_PRESS ? InputKind::KeyDown : InputKind::KeyUp, 0.f, 0.f, key});
    });
    glfwSetCharCallback(window_, [](GLFWwindow* w, unsigned int c) {
        appOf(w)->onRealEvent(InputEvent{0, InputKind::Char, 0.f, 0.f, int(c)});
    });
}

void App::onRealEvent(InputEvent e) {
    if (replaying_) return; // a replay owns the input
    e.frame = state_.frame;
    input_.apply(e);
    if (!recording_) return;
    // Keep one cursor position per frame: the last one is all a frame sees.
    if (e.kind == InputKind::Move && !recorded_.events.empty() && recorded_.events.back().kind == InputKind::Move &&
        recorded_.events.back().frame == e.frame)
        recorded_.events.back() = e;
    else
        recorded_.events.push_back(e);
}

void App::deliverScriptEvents() {
    while (scriptPos_ < script_.events.size() && script_.events[scriptPos_].frame <= state_.frame) {
        const InputEvent& e = script_.events[scriptPos_++];
        if (e.kind == InputKind::End) continue;
        input_.apply(e);
        if (recording_) recorded_.events.push_back(e); // --script with --record: a copy of what was replayed
    }
}

// ============================================================================================ [IMGUI]

void App::feedImGui() {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(input_.mouseX, input_.mouseY);
    for (int b = 0; b < 3; ++b) io.MouseDown[b] = input_.buttonHeld(b);
    io.MouseWheel += input_.wheelY;
    io.MouseWheelH += input_.wheelX;
    for (int k = 0; k < 512; ++k) io.KeysDown[k] = input_.keyHeld(k);
    io.KeyCtrl = input_.keyHeld(keys::LeftControl) || input_.keyHeld(keys::RightControl);
    io.KeyShift = input_.keyHeld(keys::LeftShift) || input_.keyHeld(keys::RightShift);
    io.KeyAlt = input_.keyHeld(keys::LeftAlt) || input_.keyHeld(keys::RightAlt);
    io.KeySuper = input_.keyHeld(keys::LeftSuper) || input_.keyHeld(keys::RightSuper);
    for (unsigned c : input_.chars) io.AddInputCharacter(c);
}

// =========================================================================================== [EVENTS]

View App::currentView() const {
    int w = 1, h = 1;
    if (window_) glfwGetWindowSize(window_, &w, &h);
    return makeView(state_.camera, float(w), float(h));
}

void App::handleEvents(bool uiMouse, bool uiKeyboard) {
    float cx = lastMouseX_, cy = lastMouseY_;
    for (const InputEvent& e : input_.pending) {
        const View view = currentView();
        const Vec2 cursor(cx, cy);
        switch (e.kind) {
        case InputKind::Move: {
            const float dx = e.x - cx, dy = e.y - cy;
            if (orbiting_) state_.camera.orbit(dx, dy);
            if (panning_) state_.camera.pan(dx, dy, view.height);
            if (orbiting_ && std::hypot(e.x - rightPressX_, e.y - rightPressY_) > 4.f) rightDragged_ = true;
            cx = e.x, cy = e.y;
            break;
        }
        case InputKind::Down:
            if (uiMouse) {
                uiOwnsButton_[e.code] = true;
                break;
            }
            if (e.code == 0) {
                switch (state_.tool) {
                case Tool::Drag:
                    rewind_.gestureStarted(world_, true);
                    if (!beginDrag(world_, state_.drag, view, cursor, world_.settings.scene.grabRadius)) state_.say("Drag: no cloth under the cursor");
                    break;
                case Tool::Wind:
                    rewind_.gestureStarted(world_, true);
                    if (!state_.tools.windFixed) state_.windBlowing = true, state_.windSource = windSourceAt(view, cursor);
                    break;
                case Tool::Impulse:
                    rewind_.gestureStarted(world_, false);
                    applyScreenImpulse(world_, view, cursor, state_.tools.radiusPx, state_.tools.impulse);
                    break;
                case Tool::Ball: {
                    rewind_.gestureStarted(world_, false);
                    const Throw t = throwBall(world_, view, cursor);
                    world_.balls.push_back(t.ball);
                    if (!t.aimed && t.neededSpeed > 0.f)
                        state_.say("Ball: too slow to reach the cursor from here (needs " +
                                         std::to_string(int(std::ceil(t.neededSpeed))) + " m/s: raise ball.speed)");
                    state_.ballFlags.resize(world_.balls.size(), 0);
                    state_.ballFlags.back() = kBallThrown;
                    state_.ballsThrown++;
                    break;
                }
                case Tool::Pin:
                    togglePinAt(world_, view, cursor);
                    break;
                case Tool::Knife:
                    rewind_.gestureStarted(world_, true); // Ctrl+Z sews the stroke's cut back
                    knifeBegin(world_, state_.knife, view, cursor);
                    break;
                case Tool::Count: break;
                }
            } else if (e.code == 1) {
                orbiting_ = true;
                rightDragged_ = false;
                rightPressX_ = cx, rightPressY_ = cy;
            } else {
                panning_ = true;
            }
            break;
        case InputKind::Up:
            if (uiOwnsButton_[e.code]) {
                uiOwnsButton_[e.code] = false;
                break;
            }
            if (e.code == 0) {
                if (state_.drag.active()) releaseDrag(world_, state_.drag, false);
                state_.windBlowing = false;
                knifeEnd(state_.knife);
                rewind_.gestureEnded(world_);
            } else if (e.code == 1) {
                // A right click without dragging reverses the impulse tool (Keserica 5.2.1).
                if (orbiting_ && !rightDragged_ && state_.tool == Tool::Impulse) {
                    rewind_.gestureStarted(world_, false);
                    applyScreenImpulse(world_, view, cursor, state_.tools.radiusPx, -state_.tools.impulse);
                }
                orbiting_ = false;
            } else {
                panning_ = false;
            }
            break;
        case InputKind::Scroll:
            if (uiMouse) break;
            if (state_.tool == Tool::Wind && !input_.keyHeld(keys::LeftControl) && !input_.keyHeld(keys::RightControl))
                state_.tools.windPressure = std::clamp(state_.tools.windPressure * std::pow(1.25f, e.y), 0.05f, 2000.f);
            else
                state_.camera.zoom(e.y);
            break;
        case InputKind::KeyDown: handleKey(e.code, uiKeyboard); break;
        case InputKind::KeyUp:
        case InputKind::Char:
        case InputKind::End: break;
        }
    }
    lastMouseX_ = input_.mouseX;
    lastMouseY_ = input_.mouseY;
}

void App::handleKey(int key, bool uiKeyboard) {
    if (uiKeyboard) return; // typing into the panel
    const bool ctrl = input_.keyHeld(keys::LeftControl) || input_.keyHeld(keys::RightControl);
    RenderOptions& r = state_.render;
    if (key >= keys::Num1 && key < keys::Num1 + int(Tool::Count)) {
        const Tool next = Tool(key - keys::Num1);
        if (next != Tool::Drag) releaseDrag(world_, state_.drag, false);
        if (next != Tool::Wind) state_.windBlowing = false;
        if (next != Tool::Knife) knifeEnd(state_.knife);
        state_.tool = next;
        return;
    }
    const bool shift = input_.keyHeld(keys::LeftShift) || input_.keyHeld(keys::RightShift);
    switch (key) {
    case keys::Q:
        if (ctrl) state_.quit = true;
        break;
    case keys::Z:
        if (ctrl) (shift ? state_.requestRedo : state_.requestUndo) = true;
        break;
    case keys::Y:
        if (ctrl) state_.requestRedo = true;
        break;
    case keys::P:
        state_.paused = !state_.paused;
        if (!state_.paused) rewind_.resume(); // on from the frame the timeline shows
        break;
    case keys::N:
        state_.paused = true;
        state_.stepRequests++;
        break;
    case keys::R: state_.requestReset = true; break;
    case keys::V:
    case keys::Home: state_.requestResetView = true; break;
    case keys::F: r.flat = !r.flat; break;
    case keys::T: r.texture = !r.texture; break;
    case keys::G: r.structuralSprings = !r.structuralSprings; break;
    case keys::H: r.bendSprings = !r.bendSprings; break;
    case keys::K: r.strainColors = !r.strainColors; break;
    case keys::M: state_.sound.muted = !state_.sound.muted; break;
    case keys::B:
        world_.balls.clear();
        state_.ballFlags.clear();
        break;
    case keys::X:
        if (state_.drag.active()) {
            releaseDrag(world_, state_.drag, true);
            state_.say("Pinned the grabbed particle");
        }
        break;
    case keys::L:
        state_.tools.windFixed = !state_.tools.windFixed;
        state_.windBlowing = false;
        if (state_.tools.windFixed) state_.windSource = windSourceAt(currentView(), Vec2(input_.mouseX, input_.mouseY));
        break;
    case keys::F1: state_.showHelp = !state_.showHelp; break;
    case keys::F2: state_.showPanel = !state_.showPanel; break;
    case keys::F12: state_.requestScreenshot = true; break;
    case keys::Escape:
        state_.showHelp = false;
        releaseDrag(world_, state_.drag, false);
        break;
    default: break;
    }
}

// ============================================================================================= [HELD]

void App::handleContinuous(float seconds, bool uiKeyboard) {
    const bool ctrl = input_.keyHeld(keys::LeftControl) || input_.keyHeld(keys::RightControl);
    if (!uiKeyboard && !ctrl) {
        auto held = [&](int k) { return input_.keys[size_t(k)] ? 1.f : 0.f; };
        const Vec3 local(held(keys::D) - held(keys::A), held(keys::Space) - held(keys::C), held(keys::W) - held(keys::S));
        if (local.squaredNorm() > 0.f) state_.camera.fly(local, seconds);
    }
    const View view = currentView();
    const Vec2 cursor(input_.mouseX, input_.mouseY);
    moveDrag(state_.drag, view, cursor);
    // Between frames (the step runs after this): the stroke since the last frame is cut now.
    if (state_.knife.held && knifeMove(world_, state_.knife, view, cursor) > 0) state_.pieces = PiecesSummary{};
    if (state_.windBlowing && !state_.tools.windFixed) state_.windSource = windSourceAt(view, cursor);
}

} // namespace clothtear::app
