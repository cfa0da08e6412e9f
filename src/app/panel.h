// The ImGui windows: the control panel (scene, simulation, quick switches, tools, view, parameters),
// the stats pane, the help overlay (F1), and the tool cursor drawn over the 3D view. They edit the
// AppState and the world's settings; anything heavier (rebuilds, scene loads, texture loads) is asked of
// the main loop through the request fields of AppState.
#pragma once
#include "app_state.h"
#include "rewind.h"
#include "clothtear/world.h"

namespace clothtear::app {

inline constexpr float kPanelWidth = 400.f; // px, the control panel on the left
inline constexpr float kStatsWidth = 300.f; // px, the stats pane on the right
inline constexpr float kTimelineHeight = 42.f; // px, the timeline bar along the bottom (and its margin)

void drawControlPanel(AppState& state, World& world);
void drawStatsPane(AppState& state, const World& world);
void drawHelpOverlay(AppState& state);
// The timeline along the bottom: Undo, Redo and a slider over the recorded frames (rewind.h).
void drawTimeline(AppState& state, const Rewind& rewind);
// Tool feedback over the view: the wind/impulse radius at the cursor, the fixed wind source, the drag line.
void drawToolHud(const AppState& state, const World& world, const View& view, float mouseX, float mouseY,
                 bool mouseOverUi);

} // namespace clothtear::app
