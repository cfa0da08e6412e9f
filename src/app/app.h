// The desktop app: a GLFW window with the renderer, the ImGui panel and the tools around one World.
//
//   app.cpp        window, GL/ImGui setup, the frame loop, screenshots, the exit report
//   app_input.cpp  input routing: GLFW callbacks and script replay -> InputState -> ImGui first, then
//                  hotkeys, camera and tools
//   app_sim.cpp    scene loading, rebuilds, the fixed-step simulation, its sound and the stats
#pragma once
#include "app_options.h"
#include "app_state.h"
#include "audio_out.h"
#include "input_state.h"
#include "raster_priority.h"
#include "renderer.h"
#include "rewind.h"
#include "sim_thread.h"
#include "sound_stream.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <vector>

struct GLFWwindow;

namespace clothtear::app {

class App {
public:
    // Runs the window until it is closed, --frames are done or the script ended. Exit status.
    int run(const AppOptions& options);

private:
    // app.cpp
    std::string openWindow();
    void closeWindow();
    void openSound(); // the audio device, or one line saying why the app is silent
    void frame(bool last);
    void serveRequests();
    void serveWorldFile();
    std::string writeScreenshot(const std::string& path);
    nlohmann::json report(double wallSeconds) const;
    nlohmann::json meanCosts(double wallSeconds) const; // the report's "mean": over the whole run
    void loadBuiltInTexture(bool numbered); // the woven default, or the numbered debug texture
    // app_input.cpp
    void installCallbacks();
    void onRealEvent(InputEvent e);
    void deliverScriptEvents();
    void feedImGui();
    void handleEvents(bool uiMouse, bool uiKeyboard);
    void handleKey(int key, bool uiKeyboard);
    void handleContinuous(float seconds, bool uiKeyboard);
    View currentView() const;
    // app_sim.cpp
    std::string loadScene(const std::string& name, bool withOverrides);
    // A world file (--load, the panel's Load) instead of the current world; "" or the message.
    std::string loadWorldFile(const std::string& path, bool withOverrides);
    void startedAnew(); // a new world: no held particle, no wind, fresh ball flags and clock
    // `message`, with what sceneWarnings says about the world appended (every particle pinned).
    std::string withWarnings(std::string message) const;
    void rebuildWorld();
    // How many steps this frame takes: one in lockstep, what the real-time clock owes, none paused
    // (but a single step asked for).
    int stepsThisFrame(double realSeconds);
    // The frame's steps: on the main thread, or on simThread_ while the frame before is drawn.
    void runSteps(int steps);
    void afterSteps(); // on the main thread once the steps are done: a blow-up pauses and says so
    void stepOnce();
    // After a step: the frame's sound to the device and, with --audio-out, to the soundtrack.
    void feedSound();
    // After an undo, redo or a frame of the timeline restored the world: let go of what the tools
    // held (their particles may not exist in the restored cloth) and redraw the topology.
    void afterRestore(const std::string& message);
    void trackBalls();
    void updateStats(double now);

    AppOptions options_;
    GLFWwindow* window_ = nullptr;
    World world_;
    Rewind rewind_; // the timeline and the undo of tears (rewind.h)
    AppState state_;
    Renderer renderer_;
    // The frame's steps while the frame before is drawn (frame(), sim_thread.h); made in run(), after
    // main() chose the OpenMP team size.
    std::optional<SimThread> simThread_;
    RasterYield rasterYield_; // what openWindow did to the software raster threads
    // sound: the world's tears as a stream (rebased when the world is replaced or restored), played
    // live through audioOut_ and, with --audio-out, kept whole for the WAV written at exit
    std::optional<audio::SoundStream> sound_;
    AudioOut audioOut_;
    std::vector<float> soundBlock_;  // this step's samples, reused
    std::vector<float> soundtrack_;  // the whole run's (--audio-out only)
    InputState input_;
    // replay and recording
    InputScript script_;
    size_t scriptPos_ = 0;
    bool replaying_ = false;
    bool recording_ = false;
    InputScript recorded_;
    bool lockstep_ = false; // one simulation step per displayed frame (replays, --frames, recording)
    nlohmann::json loaded_; // the report's "loaded" field after a world file was loaded (runner.h)
    size_t nextCut_ = 0;    // the next of options_.cuts to apply (runner.h applyDueCuts)
    // mouse ownership: a press that ImGui took stays ImGui's until released
    std::array<bool, 3> uiOwnsButton_{};
    float lastMouseX_ = 0.f, lastMouseY_ = 0.f;
    float rightPressX_ = 0.f, rightPressY_ = 0.f;
    bool rightDragged_ = false;
    bool orbiting_ = false, panning_ = false;
    double lastTime_ = 0.0;
};

} // namespace clothtear::app
