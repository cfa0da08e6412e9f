// All UI state of the app in one struct: the scene, the active tool and its settings, the camera, what
// the renderer shows, the panel's switches, the requests the panel makes to the main loop, and the
// stats shown. The World (simulation state) is kept apart, in App.
#pragma once
#include "camera.h"
#include "sim_clock.h"
#include "tools.h"

#include "clothtear/pieces.h"

#include <array>
#include <string>
#include <vector>

namespace clothtear::app {

// What the renderer shows and how it lights it (Gouraud: lighting per vertex, see shaders/cloth.vert.glsl).
struct RenderOptions {
    bool texture = true;            // texture the front of the cloth (else the tint alone)
    bool flat = false;              // flat shading: one normal per triangle, lit per fragment
    bool strainColors = false;      // colour by strain: blue (0) .. red (tear threshold)
    bool structuralSprings = false; // wireframe of the structural springs (triangle edges)
    bool bendSprings = false;       // wireframe of the bend-shear springs
    bool weakPoints = true;         // orange dots on weak points (torn edges, Onal 3.2.2)
    bool pinnedParticles = true;    // dark red dots on pinned particles
    std::array<float, 3> lightDir{0.45f, 0.8f, 0.55f};   // towards the light (normalized at use)
    std::array<float, 3> lightColor{1.f, 0.96f, 0.88f};  // diffuse and specular colour
    std::array<float, 3> ambient{0.30f, 0.32f, 0.36f};   // ambient colour
    float specular = 0.18f;                              // [0, 2]   specular strength
    float shininess = 24.f;                              // [1, 256] Blinn-Phong exponent
    std::array<float, 3> frontTint{1.f, 1.f, 1.f};       // multiplies the texture on the front
    std::array<float, 3> backColor{0.78f, 0.75f, 0.78f}; // the back: a shade of the fabric (untextured: its colour)
    bool fringe = true;       // loose threads along torn edges (render_mesh.h FringeMesh)
    bool groundShadow = true; // the cloth's soft shadow on the ground, darkest where it touches
    std::array<float, 3> sky{0.60f, 0.74f, 0.90f};       // clear colour
    std::array<float, 3> ground{0.55f, 0.57f, 0.52f};    // ground plane colour
    std::array<float, 3> ballColor{0.85f, 0.55f, 0.15f}; // thrown balls
};

// The sound of tearing, played live (audio_out.h): the panel's Sound section and M.
struct SoundOptions {
    bool muted = false;  // M; the device gets silence, --audio-out still writes the sound
    float volume = 0.8f; // [0, 1] linear gain on the device's output
    std::string status;  // "playing through SDL's <driver> driver", or why the app is silent
};

// Measured over the last half second, shown in the stats pane.
struct Stats {
    double fps = 0;          // displayed frames per second
    double simFps = 0;       // simulated frames per second (60 = real time at the default frame_dt)
    double msPerStep = 0;    // wall ms per world.step()
    std::array<double, int(Phase::Count)> phaseMs{}; // ms per step in each phase
    double drawMs = 0;       // CPU ms to issue the frame's GL and ImGui draws (smoothed)
    double swapMs = 0;       // ms in glfwSwapBuffers (with a software renderer: most of the raster work)
    size_t clothTrianglesDrawn = 0; // last frame: fewer than the cloth's when seen from far (render_lod.h)
    double limitCappedShare = 0; // share of sub-steps whose length limit ran out of passes (0..1)
    // J, of the world as the last sample saw it: a pass over every spring (half a millisecond at 128
    // x 128), so taken with the other figures, twice a second, not every frame (updateStats).
    double kineticEnergy = 0, potentialEnergy = 0;
    // px: the most any row of the stats pane has run past its right edge this run (0: every row
    // fits; the report's app.stats_pane_overflow_px, checked by a window test).
    float statsOverflowPx = 0;
    // bookkeeping for the averages
    double sampleStart = -1; // s (glfwGetTime)
    int frames = 0;
    uint64_t steps = 0;
    StepProfile profileAtStart;
    uint64_t stepsAtStart = 0;
};

// Summed over the whole run, for the report's means (App::report, "mean"): the smoothed figures of
// Stats follow the last frames only, and a run whose load changes (a drag that tears, then holds)
// ends with the cost of its quiet frames. The sums run over AppState::frame frames.
struct RunCosts {
    double drawMs = 0; // issuing the frame's draws
    double swapMs = 0; // glfwSwapBuffers
    double waitMs = 0; // waiting for the frame's steps on the simulation thread (the pipeline)
    double stepsMs = 0;  // the frame's steps with the tools, rewind checkpoint and sound (either thread)
    double serialMs = 0; // the frame's time with no steps beside it: before they start, after they end
};

inline constexpr uint8_t kBallThrown = 1, kBallTouched = 2;

// The stats pane's count of torn pieces (findPieces), recomputed only when the cloth's topology or
// masses change (a tear, a pin, a rebuild: massRevision is unique per build).
struct PiecesSummary {
    uint64_t topology = ~0ull, mass = ~0ull;
    std::vector<Piece> list; // largest first
};

struct AppState {
    // ---- scene
    std::string scene = "curtain";
    std::vector<std::string> overrides; // --set key=value from the command line, applied on scene loads
    // ---- tools
    Tool tool = Tool::Drag;
    ToolSettings tools;
    DragState drag;
    KnifeState knife;
    PiecesSummary pieces;
    WindSource windSource;    // where the wind tool blows (follows the cursor unless fixed)
    bool windBlowing = false; // the wind tool's button is held
    // ---- view
    OrbitCamera camera;
    RenderOptions render;
    SoundOptions sound;
    // ---- simulation control
    bool paused = false;
    // The pipeline (app.cpp [FRAME]): a frame's steps run on the simulation thread while the frame
    // before them is drawn. Off (--no-pipeline, or the stats pane): step, then draw.
    bool pipeline = true;
    int stepRequests = 0;     // single steps asked for while paused
    bool allowUnsafe = false; // sliders span the hard ranges instead of the safe ones (Keserica 6.2)
    SimClock clock;
    // ---- panel
    bool showPanel = true;
    bool showStats = true;
    bool showHelp = false;
    std::array<char, 512> texturePath{}; // the path field of the texture loader
    std::string textureName;       // what is loaded now
    std::string textureError;      // shown in red under the loader; the current texture stays
    std::array<char, 512> meshPath{};    // the path field of the OBJ loader (Mesh section)
    std::string meshError;               // shown in red under it; the current cloth stays
    std::array<char, 512> worldPath{};   // the path field of the world file's Save and Load (Mesh section)
    std::string worldError;              // shown in red under it; on a failed load the current cloth stays
    std::string worldFile;               // the world file loaded last ("" for none)
    std::string message;           // status line shown over the view for a few seconds (errors, screenshots)
    uint64_t messageFrame = 0;     // frame the message was set in
    // ---- requests from the panel and hotkeys, served by the main loop once per frame
    int requestScene = -1;         // index into allScenes(): that setup, on the current mesh
    bool requestReset = false;     // rebuild the cloth from the current settings
    bool requestDefaults = false;  // back to the scene's default settings
    bool requestResetView = false;
    bool requestLoadMesh = false;     // the scene's setup on the OBJ of meshPath
    bool requestBuiltInMesh = false;  // the scene's setup back on its grid or irregular mesh
    bool requestLoadTexture = false;
    bool requestDefaultTexture = false;  // the woven fabric
    bool requestNumberedTexture = false; // the numbered patches (debug: follow the UVs through a tear)
    bool requestScreenshot = false;
    bool requestExportObj = false;  // the cloth as it is, as OBJ with UVs (clothtear-FRAME.obj)
    bool requestUndo = false;       // Ctrl+Z: the last group of tears undone (rewind.h)
    bool requestRedo = false;       // Ctrl+Shift+Z or Ctrl+Y
    int requestView = -1;           // the timeline: show this recorded frame (pauses)
    int64_t requestDeletePiece = -1; // the stats pane's Delete: the piece holding this triangle
    bool requestSaveWorld = false;  // the whole world to the world file of worldPath
    bool requestLoadWorld = false;  // the world of the world file of worldPath, instead of the current one
    bool quit = false;
    // ---- counters and stats
    uint64_t frame = 0;            // displayed frames so far
    int ballsThrown = 0;
    int ballsHitCloth = 0;         // thrown balls that touched the cloth
    std::vector<uint8_t> ballFlags; // per world.balls entry: kBallThrown | kBallTouched
    Stats stats;
    RunCosts runCosts;

    void say(std::string text) {
        message = std::move(text);
        messageFrame = frame;
    }
};

} // namespace clothtear::app
