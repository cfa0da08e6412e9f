// The controls table (see controls.h).
#include "controls.h"

namespace clothtear::app {

namespace {
const ControlHelp kControls[] = {
    {"Left button", "Use the active tool (Drag, Wind, Impulse, Ball, Pin, Knife)"},
    {"1 2 3 4 5 6", "Tool: Drag / Wind / Impulse / Ball / Pin / Knife"},
    {"Drag tool", "Left drag pulls the cloth under the cursor (a patch of grab.radius); pull hard to tear"},
    {"X (while dragging)", "Pin the grabbed particle where it is and let go"},
    {"Wind tool", "Hold left to blow along the view; wheel = strength; L fixes the source"},
    {"Impulse tool", "Left click pushes away, right click pulls towards you"},
    {"Ball tool", "Left click throws a ball through the cursor; B clears balls"},
    {"Pin tool", "Left click pins / unpins the particle under the cursor"},
    {"Knife tool", "Hold left and draw across the cloth: it is cut along the stroke as you go"},
    {"Right drag", "Orbit the camera"},
    {"Middle drag", "Pan the camera"},
    {"Wheel", "Zoom (Ctrl+wheel with the wind tool)"},
    {"W A S D", "Fly forward / left / back / right"},
    {"Space / C", "Fly up / down"},
    {"V or Home", "Reset the view"},
    {"P", "Pause / resume"},
    {"N", "Single step (while paused)"},
    {"R", "Reset the cloth"},
    {"F", "Flat shading on / off"},
    {"T", "Texture on / off"},
    {"G / H", "Wireframe: structural / bend-shear springs"},
    {"K", "Strain colour map"},
    {"M", "Mute / unmute the sound of tearing"},
    {"F1", "This help"},
    {"F2", "Hide / show the panel"},
    {"F12", "Save a screenshot (clothtear-FRAME.png)"},
    {"Esc", "Close help, let go of the cloth"},
    {"Ctrl+Z", "Undo the last tears (a drag, a ball, a gust): the cloth sewn back exactly"},
    {"Ctrl+Shift+Z or Ctrl+Y", "Redo what was undone"},
    {"Timeline (bottom)", "Drag to go back in time (pauses); P resumes from the frame shown"},
    {"Ctrl+Q", "Quit"},
};
} // namespace

std::span<const ControlHelp> controlsHelp() { return kControls; }

const char* startHint() {
    return "Left drag: pull and tear    Right drag: orbit    Wheel: zoom\n"
           "1-6: tools (4 throws balls, 6 cuts)    F1: all controls";
}

} // namespace clothtear::app
