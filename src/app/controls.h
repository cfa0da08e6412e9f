// Every control of the app in one table: the help overlay (F1) lists it, and the README copies it.
#pragma once
#include <span>

namespace clothtear::app {

struct ControlHelp {
    const char* input;  // "Left drag", "F1", ...
    const char* action; // what it does
};

std::span<const ControlHelp> controlsHelp();
// The one-line hint the window shows for its first seconds: the few controls a first run needs.
const char* startHint();

// GLFW key codes the app binds (values of GLFW_KEY_*; checked against glfw3.h in app.cpp).
namespace keys {
inline constexpr int Space = 32, Num1 = 49, A = 65, B = 66, C = 67, D = 68, E = 69, F = 70, G = 71, H = 72, K = 75,
                     L = 76, M = 77, N = 78, P = 80, Q = 81, R = 82, S = 83, T = 84, V = 86, W = 87, X = 88, Y = 89, Z = 90,
                     Escape = 256, Home = 268, F1 = 290, F2 = 291, F12 = 301, LeftShift = 340, LeftControl = 341,
                     LeftAlt = 342, LeftSuper = 343, RightShift = 344, RightControl = 345, RightAlt = 346,
                     RightSuper = 347;
}

} // namespace clothtear::app
