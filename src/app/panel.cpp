// ImGui windows of the app.
//
// Section index:
//   [PANEL]   scene, simulation, quick switches, tools, view, texture, mesh, parameters, sound
//   [STATS]   FPS, ms per phase, counts, tears per mode, energy, strain
//   [HELP]    the controls table
//   [HUD]     tool cursor over the view
#include "panel.h"

#include "controls.h"
#include "param_widgets.h"

#include "clothtear/params.h"
#include "clothtear/pieces.h"
#include "clothtear/scenes.h"

#include <imgui.h>
#include <imgui_internal.h> // ImGuiWindow::DC.CursorMaxPos: the stats pane's widest row
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>

namespace clothtear::app {
namespace {

bool toggleParam(Settings& s, const char* name, const char* label) {
    const ParamInfo* p = findParam(name);
    if (!p) return false;
    bool v = getParam(s, *p) != 0.0;
    const bool changed = ImGui::Checkbox(label, &v);
    if (changed) setParamUnchecked(s, *p, v ? 1.0 : 0.0);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s: %s", p->name, p->help);
    return changed;
}

void colorEdit(const char* label, std::array<float, 3>& c) {
    ImGui::ColorEdit3(label, c.data(), ImGuiColorEditFlags_NoInputs);
}

void toolOptions(AppState& st, World& world) {
    ToolSettings& t = st.tools;
    switch (st.tool) {
    case Tool::Drag:
        // Three lines: the texture tests click the sections below at fixed places.
        ImGui::TextWrapped("Left drag pulls the cloth within the radius below in the camera-facing plane; pull "
                           "hard to tear. X pins it where it is.");
        ImGui::SliderFloat("max speed", &t.maxDragSpeed, 1.f, 500.f, "%.0f m/s", ImGuiSliderFlags_Logarithmic);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("How fast the grabbed particle may chase the cursor");
        paramWidgets(world.settings, "grab.", st.allowUnsafe);
        break;
    case Tool::Wind:
        ImGui::SliderFloat("strength", &t.windPressure, 0.f, 2000.f, "%.3g Pa",
                           ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Force per square metre of cloth at the centre (wheel changes it)");
        ImGui::SliderFloat("radius", &t.radiusPx, 5.f, 400.f, "%.0f px", ImGuiSliderFlags_AlwaysClamp);
        if (ImGui::Checkbox("fix source here (L)", &t.windFixed) && !t.windFixed) st.windBlowing = false;
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("The wind keeps blowing from where it is now, also when the camera moves");
        break;
    case Tool::Impulse:
        ImGui::SliderFloat("impulse", &t.impulse, 0.f, 50.f, "%.2f m/s", ImGuiSliderFlags_AlwaysClamp);
        ImGui::SliderFloat("radius", &t.radiusPx, 5.f, 400.f, "%.0f px", ImGuiSliderFlags_AlwaysClamp);
        ImGui::TextDisabled("Left click pushes, right click pulls.");
        break;
    case Tool::Ball:
        paramWidgets(world.settings, "ball.", st.allowUnsafe);
        break;
    case Tool::Pin:
        ImGui::TextWrapped("Left click pins or unpins the particle under the cursor.");
        break;
    case Tool::Knife:
        ImGui::TextWrapped("Hold left and draw across the cloth: it is cut along the stroke, following the "
                           "cloth as it moves. Ctrl+Z sews a stroke back.");
        ImGui::Text("knife: %llu strokes, %llu springs cut", (unsigned long long)world.tearLog.knifeCuts,
                    (unsigned long long)world.tearLog.counts[int(TearMode::Knife)]);
        break;
    case Tool::Count: break;
    }
}

void viewSection(AppState& st) {
    RenderOptions& r = st.render;
    ImGui::Checkbox("texture (T)", &r.texture);
    ImGui::SameLine();
    ImGui::Checkbox("flat (F)", &r.flat);
    ImGui::SameLine();
    ImGui::Checkbox("strain (K)", &r.strainColors);
    ImGui::TextDisabled("Overlays");
    ImGui::Checkbox("structural springs (G)", &r.structuralSprings);
    ImGui::Checkbox("bend-shear springs (H)", &r.bendSprings);
    ImGui::Checkbox("weak points", &r.weakPoints);
    ImGui::SameLine();
    ImGui::Checkbox("pinned", &r.pinnedParticles);
    ImGui::TextDisabled("Light (Gouraud: per-vertex lighting)");
    ImGui::SliderFloat3("direction", r.lightDir.data(), -1.f, 1.f, "%.2f");
    colorEdit("light", r.lightColor);
    ImGui::SameLine();
    colorEdit("ambient", r.ambient);
    ImGui::SameLine();
    colorEdit("front tint", r.frontTint);
    colorEdit("back", r.backColor);
    ImGui::SameLine();
    colorEdit("sky", r.sky);
    ImGui::SameLine();
    colorEdit("ground", r.ground);
    ImGui::SameLine();
    colorEdit("balls", r.ballColor);
    ImGui::SliderFloat("specular", &r.specular, 0.f, 2.f, "%.2f");
    ImGui::SliderFloat("shininess", &r.shininess, 1.f, 256.f, "%.0f", ImGuiSliderFlags_Logarithmic);
    if (ImGui::Button("Reset view (V)")) st.requestResetView = true;
    // Below the rest: nothing above moves.
    ImGui::Checkbox("torn threads", &r.fringe);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Loose threads along the edges made by tearing (not along the hem)");
    ImGui::SameLine();
    ImGui::Checkbox("ground shadow", &r.groundShadow);
}

// A loader's error, in red under it (nothing when empty).
void errorText(const std::string& error) {
    if (error.empty()) return;
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.f, 0.4f, 0.35f, 1.f));
    ImGui::TextWrapped("%s", error.c_str());
    ImGui::PopStyleColor();
}

// "Now: FILE" on one line whatever the path's length (the full path in its tooltip): the buttons
// below stay where they are on every machine, however deep the install directory.
void currentFileText(const std::string& path) {
    const std::string name = std::filesystem::path(path).filename().string();
    ImGui::Text("Now: %s", name.empty() ? path.c_str() : name.c_str());
    if (ImGui::IsItemHovered() && name != path) ImGui::SetTooltip("%s", path.c_str());
}

// The world file (docs/world-file.md): the whole state saved, or loaded to continue exactly. Below
// the mesh loader, so that nothing above it moves (the window tests click at fixed places). No
// Enter action: a path typed to save to must not load that file over the current cloth.
void worldFileRow(AppState& st) {
    ImGui::TextDisabled("World file (the whole state, to continue exactly)");
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.62f);
    ImGui::InputTextWithHint("##worldpath", "path/to/world.ctw", st.worldPath.data(), st.worldPath.size());
    ImGui::SameLine();
    if (ImGui::Button("Save##world")) st.requestSaveWorld = true;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Write the world as it is now (cloth, balls, parameters, time) to the file");
    ImGui::SameLine();
    if (ImGui::Button("Load##world")) st.requestLoadWorld = true;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Replace the world by the file's: it continues where it was saved");
    errorText(st.worldError);
}

// An OBJ mesh for the current setup (curtain, pull, ball...): scenes compose a mesh with a setup.
void meshSection(AppState& st) {
    const Result<SceneName> scene = parseSceneName(st.scene);
    const bool obj = scene.ok() && !scene.value.objPath.empty();
    if (obj) currentFileText(scene.value.objPath);
    else ImGui::Text("Now: built-in (Parameters > Cloth > mesh)");
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x);
    const bool enter = ImGui::InputTextWithHint("##meshpath", "path/to/mesh.obj", st.meshPath.data(), st.meshPath.size(),
                                                ImGuiInputTextFlags_EnterReturnsTrue);
    if (ImGui::Button("Load OBJ") || enter) st.requestLoadMesh = true;
    ImGui::SameLine();
    if (ImGui::Button("Built-in mesh")) st.requestBuiltInMesh = true;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Back to the grid or irregular mesh of the parameters");
    ImGui::SameLine();
    if (ImGui::Button("Export OBJ")) st.requestExportObj = true;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Write the cloth as it is now, torn, with its UVs to clothtear-FRAME.obj");
    errorText(st.meshError);
    worldFileRow(st);
}

void textureSection(AppState& st) {
    currentFileText(st.textureName);
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.62f);
    const bool enter = ImGui::InputTextWithHint("##texpath", "path/to/image.png or .jpg", st.texturePath.data(),
                                                st.texturePath.size(), ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if (ImGui::Button("Load") || enter) st.requestLoadTexture = true;
    ImGui::SameLine();
    if (ImGui::Button("Default")) st.requestDefaultTexture = true;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("The woven fabric (assets/woven.png)");
    // The debug texture on a row of its own: the path field's row above keeps its places.
    if (ImGui::Button("Numbered (debug)")) st.requestNumberedTexture = true;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("64 numbered patches (assets/numbered.png): each number stays whole on a torn piece");
    errorText(st.textureError);
}

// Live sound (audio_out.h): mute and volume act on the device at its next callback. Last in the
// panel, so nothing above it moves (the window tests click at fixed places).
void soundSection(AppState& st) {
    SoundOptions& s = st.sound;
    ImGui::Checkbox("mute (M)", &s.muted);
    ImGui::SameLine();
    float percent = s.volume * 100.f;
    if (ImGui::SliderFloat("volume", &percent, 0.f, 100.f, "%.0f %%", ImGuiSliderFlags_AlwaysClamp))
        s.volume = percent / 100.f;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Gain on the sound of tearing (--audio-out writes it at full volume)");
    ImGui::TextDisabled("%s", s.status.c_str());
}

} // namespace

// ============================================================================================ [PANEL]

void drawControlPanel(AppState& st, World& world) {
    if (!st.showPanel) return;
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(kPanelWidth, io.DisplaySize.y), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.88f);
    ImGui::Begin("clothtear", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                           ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings);
    ImGui::PushItemWidth(ImGui::GetContentRegionAvail().x * 0.58f);

    // Scene picker: every scene of the headless runner.
    const auto scenes = allScenes();
    const Result<SceneName> current = parseSceneName(st.scene);
    const char* setup = current.ok() ? current.value.setup->name : st.scene.c_str();
    if (ImGui::BeginCombo("scene", setup)) {
        for (int i = 0; i < int(scenes.size()); ++i) {
            if (ImGui::Selectable(scenes[i].name, std::string_view(setup) == scenes[i].name)) st.requestScene = i;
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", scenes[i].description);
        }
        ImGui::EndCombo();
    }
    if (ImGui::Button("Reset (R)")) st.requestReset = true;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Rebuild the cloth with the current parameters");
    ImGui::SameLine();
    if (ImGui::Button("Defaults")) st.requestDefaults = true;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Every parameter back to the scene's default");
    ImGui::SameLine();
    ImGui::Checkbox("Pause (P)", &st.paused);
    ImGui::SameLine();
    if (ImGui::Button("Step (N)")) st.paused = true, st.stepRequests++;

    // Quick switches (each is a row of the parameter table).
    toggleParam(world.settings, "tear.enabled", "Tearing");
    ImGui::SameLine();
    toggleParam(world.settings, "wind.enabled", "Wind");
    ImGui::SameLine();
    toggleParam(world.settings, "collision.ground", "Ground");
    ImGui::SameLine();
    if (ImGui::Button("Clear balls (B)")) world.balls.clear(), st.ballFlags.clear();

    ImGui::Separator();
    for (int i = 0; i < int(Tool::Count); ++i) {
        if (i) ImGui::SameLine();
        const std::string label = std::string(toolName(Tool(i))) + "##tool";
        if (ImGui::RadioButton(label.c_str(), st.tool == Tool(i))) st.tool = Tool(i);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Hotkey %d", i + 1);
    }
    toolOptions(st, world);
    ImGui::Separator();

    if (ImGui::CollapsingHeader("View")) viewSection(st);
    if (ImGui::CollapsingHeader("Texture")) textureSection(st);
    if (ImGui::CollapsingHeader("Mesh")) meshSection(st);
    if (ImGui::CollapsingHeader("Parameters", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::Checkbox("allow unsafe values", &st.allowUnsafe);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Sliders span the hard ranges: push the simulation past its stable range on purpose.");
        if (parameterGroups(world.settings, st.allowUnsafe)) st.requestReset = true;
    }
    if (ImGui::CollapsingHeader("Sound", ImGuiTreeNodeFlags_DefaultOpen)) soundSection(st);
    ImGui::PopItemWidth();
    ImGui::End();
}

// ============================================================================================ [STATS]

namespace {

// printf into a std::string (a row of the stats pane, up to 159 characters).
template <class... Args> std::string formatRow(const char* format, Args... args) {
    char row[160];
    std::snprintf(row, sizeof row, format, args...);
    return row;
}

// Whether `text`, after `lead` px of widget (a tree node's arrow), fits the rest of the pane's row.
bool fitsRow(const std::string& text, float lead = 0.f) {
    return lead + ImGui::CalcTextSize(text.c_str()).x <= ImGui::GetContentRegionAvail().x;
}

// The torn pieces: how many and the smallest; opened, each with its area, mass and a Delete button
// (the main loop takes the piece out; Ctrl+Z brings it back).
void piecesList(AppState& st, const std::vector<Piece>& pieces) {
    if (pieces.size() <= 1) {
        ImGui::Text("pieces %zu", pieces.size());
        return;
    }
    size_t asleep = 0;
    for (const Piece& p : pieces) asleep += p.asleep;
    // The smallest piece's area leaves the header (for a tooltip) where the header would not fit.
    const std::string counts = asleep > 0 ? formatRow("pieces %zu, %zu asleep", pieces.size(), asleep)
                                          : formatRow("pieces %zu", pieces.size());
    const std::string full = counts + formatRow(" (smallest %.3g m^2)", pieces.back().restArea);
    const bool headerFits = fitsRow(full, ImGui::GetTreeNodeToLabelSpacing());
    const bool open = ImGui::TreeNode("pieces", "%s", headerFits ? full.c_str() : counts.c_str());
    if (!headerFits && ImGui::IsItemHovered()) ImGui::SetTooltip("smallest %.3g m^2", pieces.back().restArea);
    if (!open) return;
    constexpr size_t kShown = 12;
    for (size_t k = 0; k < pieces.size() && k < kShown; ++k) {
        const Piece& p = pieces[k];
        ImGui::PushID(int(k));
        if (ImGui::SmallButton("Delete")) st.requestDeletePiece = int64_t(p.firstTriangle);
        ImGui::SameLine();
        // Area, mass and triangles; the mass to a tooltip where the row would not fit (a small
        // piece's "4.29e-05 m^2  0.00858 g" ran past the pane).
        const std::string row = formatRow("%.3g m^2  %.3g g  %zu tri.", p.restArea, 1000.0 * p.mass, p.triangles);
        const bool fits = fitsRow(row);
        const std::string shown = fits ? row : formatRow("%.3g m^2  %zu tri.", p.restArea, p.triangles);
        // A sleeping piece (settled, not simulated until touched: piece_sleep.cpp) is greyed.
        if (p.asleep) ImGui::TextDisabled("%s", shown.c_str());
        else ImGui::TextUnformatted(shown.c_str());
        if (ImGui::IsItemHovered() && (p.asleep || !fits)) {
            std::string tip = fits ? "" : formatRow("%.3g g", 1000.0 * p.mass);
            if (p.asleep) tip += (tip.empty() ? "" : "\n") + std::string("Asleep: it settled and is not simulated until touched");
            ImGui::SetTooltip("%s", tip.c_str());
        }
        ImGui::PopID();
    }
    if (pieces.size() > kShown) ImGui::TextDisabled("... %zu smaller", pieces.size() - kShown);
    ImGui::TreePop();
}

// A row of the fixed-width stats pane: `full`, or `compact` where `full` would run past the pane's
// edge (large counts), with `tooltip` (if any) saying what the compact one's figures are.
void fittedText(const std::string& full, const std::string& compact, const char* tooltip) {
    const bool fits = fitsRow(full);
    ImGui::TextUnformatted(fits ? full.c_str() : compact.c_str());
    if (!fits && *tooltip && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip);
}

} // namespace

void drawStatsPane(AppState& st, const World& world) {
    if (!st.showStats) return;
    const ImGuiIO& io = ImGui::GetIO();
    const float width = kStatsWidth;
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - width - 8.f, 8.f), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(width, 0.f), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.7f);
    ImGui::Begin("Stats", &st.showStats, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                             ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing);
    const Stats& s = st.stats;
    const Cloth& c = world.cloth;
    if (s.fps > 0) ImGui::Text("FPS %.1f   sim %.1f frames/s", s.fps, s.simFps);
    else ImGui::TextDisabled("FPS --   (timed every half second)"); // not "FPS 0.0" at start
    if (st.paused) ImGui::TextColored(ImVec4(1.f, 0.85f, 0.3f, 1.f), "paused");
    else if (st.clock.slowedDown)
        ImGui::TextColored(ImVec4(1.f, 0.6f, 0.3f, 1.f), "slower than real time (%.0f%%)",
                           100.0 * s.simFps * world.settings.time.frameDt);
    ImGui::Text("step %.2f ms  (%d sub-steps)", s.msPerStep, world.frameSubsteps);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Sub-steps of the last frame: the stability guard takes as many as the material\n"
                          "needs to keep the stiffness you set (a finer or smaller cloth needs more),\n"
                          "up to time.max_substeps.");
    // On its own line: appended to the one above it ran past the pane's edge.
    if (world.profile.dampingImplicit) {
        ImGui::TextDisabled("damping taken implicitly");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("The springs' damping alone would need more sub-steps than time.max_substeps,\n"
                              "or more than the implicit damping's dearer sub-steps cost: it is taken\n"
                              "implicitly (time.damping = auto), stable at the stiffness's step.");
    }
    // A capped spring may keep all of its stiffness and lose damping only (the light particles a
    // ball's tears make): "at 100% stiffness" under "softer than set" read as a contradiction.
    if (world.guardCappedSprings > 0 && world.guardStiffnessKept < 0.995f)
        ImGui::TextColored(ImVec4(1.f, 0.85f, 0.3f, 1.f), "softer than set, to stay stable:\n  %zu springs at %.0f%% stiffness",
                           world.guardCappedSprings, 100.0 * world.guardStiffnessKept);
    else if (world.guardCappedSprings > 0)
        ImGui::TextColored(ImVec4(1.f, 0.85f, 0.3f, 1.f), "less damped than set, to stay stable:\n  %zu springs at %.0f%% damping",
                           world.guardCappedSprings, 100.0 * world.guardDampingKept);
    else
        ImGui::TextDisabled("stiffness as you set it");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Where the sub-steps the material needs exceed time.max_substeps, or for the light\n"
                          "particles tearing makes, the guard caps springs so the step stays stable: the\n"
                          "cloth is softer there than you set (the stiffness the most softened spring kept;\n"
                          "its damping kept %.0f%%). Raise time.max_substeps to keep it.",
                          100.0 * world.guardDampingKept);
    // Neutral, not a warning: a cloth being pulled or hit runs out of passes as a matter of course;
    // a cloth at rest or in light wind that does is stretched past the limit (README, known gaps).
    if (s.limitCappedShare > 0.0)
        ImGui::TextDisabled("stretch over limit: %.0f%% of sub-steps", 100.0 * s.limitCappedShare);
    else
        ImGui::TextDisabled("stretch kept within the limit");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The length limit (limit.max_stretch) pulls over-stretched springs back each\n"
                          "sub-step in a bounded number of passes (with gauss-seidel up to 4 x the\n"
                          "cloth's depth in springs, but an eighth of it while you drag: the hand may\n"
                          "stretch the cloth). When they run out, the cloth ends the sub-step stretched\n"
                          "further: normal while you pull or a ball hits, a solver gap at rest.");
    ImGui::Text("draw %.1f ms   swap %.1f ms", s.drawMs, s.swapMs);
    // Per-phase timings are for engineers: folded, so the pane fits a small window.
    if (ImGui::TreeNode("time per phase")) {
        // Here, folded, so that the pane's rows below (the pieces list) stay where scripts click them.
        ImGui::Checkbox("step while drawing", &st.pipeline);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("On: the next frame is simulated on its own thread while this one is drawn, so\n"
                              "the screen shows the cloth one frame later, and a software renderer and the\n"
                              "simulation share the cores instead of taking turns. Off: step, then draw.\n"
                              "The simulation is the same either way.");
        if (ImGui::BeginTable("phases", 2, ImGuiTableFlags_SizingStretchProp)) {
            for (int p = 0; p < int(Phase::Count); ++p) {
                ImGui::TableNextColumn();
                ImGui::TextDisabled("%s", phaseName(Phase(p)));
                ImGui::TableNextColumn();
                ImGui::Text("%.3f ms", s.phaseMs[p]);
            }
            ImGui::EndTable();
        }
        ImGui::TreePop();
    }
    ImGui::Separator();
    size_t pinned = 0, weak = 0;
    for (uint8_t f : c.flags) pinned += (f & kPinned) != 0, weak += (f & kWeak) != 0;
    fittedText(formatRow("particles %zu (pinned %zu, weak %zu)", c.particleCount(), pinned, weak),
               formatRow("particles %zu (%zu / %zu)", c.particleCount(), pinned, weak),
               "particles (pinned / weak: a tear's tip)");
    ImGui::Text("springs %zu + bend-shear %zu", c.springs.size(), c.bends.size());
    if (s.clothTrianglesDrawn > 0 && s.clothTrianglesDrawn < c.triangles.size())
        ImGui::Text("triangles %zu (%zu drawn)", c.triangles.size(), s.clothTrianglesDrawn);
    else
        ImGui::Text("triangles %zu", c.triangles.size());
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("From far, where a grid cell spans under 3 pixels, every intact block of 2 x 2 cells\n"
                          "is drawn as two triangles (torn blocks as they are): the same image at about\n"
                          "a quarter of the triangles. Zoom in to draw every triangle.");
    const auto basic = (unsigned long long)world.tearLog.counts[0], weakTears = (unsigned long long)world.tearLog.counts[1],
               onePoint = (unsigned long long)world.tearLog.counts[2];
    fittedText(formatRow("tears: basic %llu  weak %llu  one-point %llu", basic, weakTears, onePoint),
               formatRow("tears: %llu / %llu / %llu", basic, weakTears, onePoint),
               "Tears by mode (Onal 3.2): basic / weak point / one-point connection");
    PiecesSummary& ps = st.pieces;
    if (ps.topology != c.topologyRevision || ps.mass != c.massRevision)
        ps = {c.topologyRevision, c.massRevision, findPieces(c)};
    piecesList(st, ps.list);
    const double ke = s.kineticEnergy, pe = s.potentialEnergy; // sampled with the rates above (updateStats)
    // Two rows: on one, a small kinetic energy ("0.000618") and a potential one ran past the pane.
    ImGui::Text("energy: kinetic %.3g J", ke);
    ImGui::Text("        potential %.3g J", pe);
    ImGui::Text("max strain %.3f (tears at %.2f)", world.maxStrain, world.settings.tear.threshold);
    size_t ballsAsleep = 0;
    for (const Ball& b : world.balls) ballsAsleep += b.asleep;
    if (ballsAsleep > 0) {
        ImGui::Text("balls %zu, %zu asleep   t = %.2f s", world.balls.size(), ballsAsleep, world.time);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Asleep: at rest with no moving cloth within reach, not simulated until touched");
    } else {
        ImGui::Text("balls %zu   t = %.2f s", world.balls.size(), world.time);
    }
    if (!world.finite) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.f, 0.3f, 0.3f, 1.f));
        ImGui::TextWrapped("NON-FINITE: %s", world.nonFiniteWhere.c_str()); // a phase's name and where: may be long
        ImGui::PopStyleColor();
    }
    ImGui::TextDisabled("F1: help");
    // The widest row drawn against the pane's inner edge (imgui_internal.h: CursorMaxPos grows with
    // every item, text included, whether or not the pane clips it).
    const ImGuiWindow* pane = ImGui::GetCurrentWindow();
    st.stats.statsOverflowPx = std::max(st.stats.statsOverflowPx, pane->DC.CursorMaxPos.x - pane->WorkRect.Max.x);
    ImGui::End();
}

// ============================================================================================= [HELP]

void drawHelpOverlay(AppState& st) {
    if (!st.showHelp) return;
    const ImGuiIO& io = ImGui::GetIO();
    // Centred in the view right of the panel: centred on the whole window it lay under the panel,
    // and a click on the panel brought the panel to the front, over the help's key column.
    const float left = st.showPanel ? kPanelWidth : 0.f;
    ImGui::SetNextWindowPos(ImVec2(left + (io.DisplaySize.x - left) * 0.5f, io.DisplaySize.y * 0.5f), ImGuiCond_Always,
                            ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowBgAlpha(0.92f);
    ImGui::Begin("Controls (F1)", &st.showHelp, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings);
    if (ImGui::BeginTable("controls", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) {
        for (const ControlHelp& c : controlsHelp()) {
            ImGui::TableNextColumn();
            ImGui::TextColored(ImVec4(1.f, 0.85f, 0.45f, 1.f), "%s", c.input);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(c.action);
        }
        ImGui::EndTable();
    }
    ImGui::TextDisabled("The panel gets the mouse and keyboard first when the cursor is over it.");
    ImGui::End();
}

// ============================================================================================== [HUD]

void drawToolHud(const AppState& st, const World& world, const View& view, float mx, float my, bool overUi) {
    ImDrawList* dl = ImGui::GetForegroundDrawList();
    // Status line: the last message, for about five seconds, at the bottom of the view.
    if (!st.message.empty() && st.frame - st.messageFrame < 300) {
        const ImVec2 size = ImGui::CalcTextSize(st.message.c_str());
        const float left = st.showPanel ? kPanelWidth : 0.f;
        const float right = view.width - (st.showStats ? kStatsWidth + 8.f : 0.f);
        const ImVec2 pos(0.5f * (left + right - size.x), view.height - kTimelineHeight - size.y - 10.f); // above the timeline
        dl->AddRectFilled(ImVec2(pos.x - 8.f, pos.y - 4.f), ImVec2(pos.x + size.x + 8.f, pos.y + size.y + 4.f),
                          IM_COL32(20, 20, 28, 200), 4.f);
        dl->AddText(pos, IM_COL32(255, 235, 180, 255), st.message.c_str());
    }
    // The controls a first run needs, at the top of the view for ten seconds, fading out.
    constexpr uint64_t kHintFrames = 600, kHintFade = 120;
    if (st.frame < kHintFrames && !st.showHelp) {
        const float alpha = std::min(1.f, float(kHintFrames - st.frame) / float(kHintFade));
        const ImVec2 size = ImGui::CalcTextSize(startHint());
        const float left = st.showPanel ? kPanelWidth : 0.f;
        const float right = view.width - (st.showStats ? kStatsWidth + 8.f : 0.f);
        const ImVec2 pos(std::max(left + 8.f, 0.5f * (left + right - size.x)), 12.f);
        dl->AddRectFilled(ImVec2(pos.x - 10.f, pos.y - 6.f), ImVec2(pos.x + size.x + 10.f, pos.y + size.y + 6.f),
                          IM_COL32(20, 20, 28, int(210 * alpha)), 5.f);
        // Each line centred on its own.
        const char* text = startHint();
        float y = pos.y;
        for (const char* line = text; *line;) {
            const char* end = line;
            while (*end && *end != '\n') ++end;
            const float w = ImGui::CalcTextSize(line, end).x;
            dl->AddText(ImVec2(pos.x + 0.5f * (size.x - w), y), IM_COL32(235, 240, 255, int(255 * alpha)), line, end);
            y += ImGui::GetTextLineHeight();
            line = *end ? end + 1 : end;
        }
    }
    const ImU32 wind = IM_COL32(90, 170, 255, 200), impulse = IM_COL32(255, 190, 60, 200);
    if (!overUi && (st.tool == Tool::Wind || st.tool == Tool::Impulse))
        dl->AddCircle(ImVec2(mx, my), st.tools.radiusPx, st.tool == Tool::Wind ? wind : impulse, 48, 1.5f);
    if (st.tool == Tool::Wind && !overUi) {
        const std::string label = std::to_string(int(st.tools.windPressure + 0.5f)) + " Pa";
        dl->AddText(ImVec2(mx + 11.f, my + 11.f), IM_COL32(0, 0, 0, 200), label.c_str());
        dl->AddText(ImVec2(mx + 10.f, my + 10.f), IM_COL32(255, 255, 255, 255), label.c_str());
    }
    if (st.tools.windFixed) {
        const Vec2& c = st.windSource.center;
        dl->AddCircle(ImVec2(c.x(), c.y()), st.tools.radiusPx, wind, 48, 2.5f);
        dl->AddText(ImVec2(c.x() - 18.f, c.y() - 6.f), wind, "wind");
    }
    if (st.knife.trail.size() > 1) { // the stroke while the knife is held, a thin line
        std::vector<ImVec2> points;
        for (const Vec2& p : st.knife.trail) points.emplace_back(p.x(), p.y());
        dl->AddPolyline(points.data(), int(points.size()), IM_COL32(250, 250, 255, 220), ImDrawFlags_None, 1.5f);
    }
    if (st.drag.active() && st.drag.particle < world.cloth.particleCount()) {
        Vec2 a, b;
        if (projectToWindow(view.viewProjection, world.cloth.x[st.drag.particle], view.width, view.height, a) &&
            projectToWindow(view.viewProjection, st.drag.target, view.width, view.height, b)) {
            dl->AddLine(ImVec2(a.x(), a.y()), ImVec2(b.x(), b.y()), IM_COL32(255, 80, 60, 220), 2.f);
            dl->AddCircleFilled(ImVec2(a.x(), a.y()), 4.f, IM_COL32(255, 80, 60, 255));
        }
    }
}

// A bar between the panel and the stats pane, at the bottom of the window. Dragging the slider shows
// a recorded frame (the main loop restores it and pauses); P resumes from it.
void drawTimeline(AppState& st, const Rewind& rewind) {
    const History& h = rewind.history();
    if (h.size() == 0) return;
    const ImGuiIO& io = ImGui::GetIO();
    const float left = (st.showPanel ? kPanelWidth : 0.f) + 8.f;
    const float right = io.DisplaySize.x - (st.showStats ? kStatsWidth + 16.f : 8.f);
    ImGui::SetNextWindowPos(ImVec2(left, io.DisplaySize.y - kTimelineHeight), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(std::max(320.f, right - left), kTimelineHeight - 8.f), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.75f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove |
                                   ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoSavedSettings;
    ImGui::Begin("##timeline", nullptr, flags);
    ImGui::BeginDisabled(!rewind.canUndo());
    if (ImGui::Button("Undo")) st.requestUndo = true;
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("Ctrl+Z: the last tears sewn back (%zu to undo)", rewind.undoCount());
    ImGui::SameLine();
    ImGui::BeginDisabled(!rewind.canRedo());
    if (ImGui::Button("Redo")) st.requestRedo = true;
    ImGui::EndDisabled();
    ImGui::SameLine();
    const bool viewing = rewind.viewing() >= 0;
    int shown = viewing ? rewind.viewing() : int(h.size()) - 1;
    char label[48];
    std::snprintf(label, sizeof label, "t = %.2f s", h.at(size_t(shown)).time());
    char note[64];
    if (viewing) std::snprintf(note, sizeof note, "rewound: P resumes here");
    else std::snprintf(note, sizeof note, "%.1f s kept, %.0f MB", h.at(h.size() - 1).time() - h.at(0).time(), double(h.bytes()) / 1e6);
    ImGui::SetNextItemWidth(std::max(80.f, ImGui::GetContentRegionAvail().x - ImGui::CalcTextSize(note).x - 12.f));
    if (ImGui::SliderInt("##time", &shown, 0, int(h.size()) - 1, label, ImGuiSliderFlags_AlwaysClamp))
        st.requestView = shown;
    ImGui::SameLine();
    ImGui::TextUnformatted(note);
    ImGui::End();
}

} // namespace clothtear::app
