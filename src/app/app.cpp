// The app: window and GL/ImGui setup, the frame loop, screenshots and the exit report.
//
// Section index:
//   [RUN]      run(): script and scene first (clean errors before any window), then the loop
//   [WINDOW]   GLFW window, GLEW, renderer, ImGui; the no-display message
//   [FRAME]    one frame: input -> ImGui -> tools -> panel -> requests -> simulation -> draw -> swap
//   [REQUESTS] scene picks, resets, texture loads, world files asked for by the panel and hotkeys
//   [OUTPUT]   screenshot, recorded script, JSON report
#include "app.h"

#include "controls.h"
#include "image_io.h"
#include "panel.h"
#include "runner.h"
#include "wav_file.h"

#include "clothtear/params.h"
#include "clothtear/scenes.h"
#include "clothtear/world_file.h"

#define GLFW_INCLUDE_NONE
#include <GL/glew.h>
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>

// The key codes of controls.h and key_names.cpp are GLFW's.
static_assert(clothtear::app::keys::A == GLFW_KEY_A && clothtear::app::keys::F1 == GLFW_KEY_F1 &&
              clothtear::app::keys::Escape == GLFW_KEY_ESCAPE && clothtear::app::keys::Space == GLFW_KEY_SPACE &&
              clothtear::app::keys::LeftControl == GLFW_KEY_LEFT_CONTROL &&
              clothtear::app::keys::RightSuper == GLFW_KEY_RIGHT_SUPER && clothtear::app::keys::F12 == GLFW_KEY_F12 &&
              clothtear::app::keys::Home == GLFW_KEY_HOME && clothtear::app::keys::M == GLFW_KEY_M && GLFW_MOUSE_BUTTON_RIGHT == 1 && GLFW_MOUSE_BUTTON_MIDDLE == 2);

// The PNGs tools/make_fabric.cpp writes at build time (src/app/CMakeLists.txt).
#ifndef CLOTHTEAR_DEFAULT_TEXTURE
#define CLOTHTEAR_DEFAULT_TEXTURE ""
#endif
#ifndef CLOTHTEAR_NUMBERED_TEXTURE
#define CLOTHTEAR_NUMBERED_TEXTURE ""
#endif

namespace clothtear::app {
namespace {

std::string g_glfwError; // last GLFW error, for the one-line messages (GLFW reports through a C callback)
// Ctrl+C or kill in the terminal ends the loop normally, so --record and --json files are still written.
volatile std::sig_atomic_t g_stopRequested = 0;

constexpr int kWindowWidth = 1280, kWindowHeight = 720;
// The nice value of a software renderer's raster threads (raster_priority.h; measured in bench/README.md,
// "The raster threads yield").
constexpr int kRasterNiceness = 10;

} // namespace

// ============================================================================================== [RUN]

int App::run(const AppOptions& options) {
    options_ = options;
    state_.overrides = options.sets;
    if (!options.script.empty()) {
        Result<InputScript> loaded = loadInputScript(options.script);
        if (!loaded.ok()) {
            std::cerr << "clothtear: " << loaded.error << "\n";
            return 2;
        }
        script_ = std::move(loaded.value);
        replaying_ = true;
    }
    recording_ = !options.record.empty();
    if (recording_ && !std::ofstream(options.record)) {
        std::cerr << "clothtear: cannot write the input recording to '" << options.record << "'\n";
        return 2;
    }
    // A replay must see the same simulation as the recording: one step per displayed frame.
    lockstep_ = replaying_ || recording_ || options.frames >= 0;
    // --load: the window opens on the world file's cloth (parseRunOptions refused --scene with it).
    const std::string err = options.load.empty() ? loadScene(options.scene, true) : loadWorldFile(options.load, true);
    if (!err.empty()) {
        std::cerr << "clothtear: " << err << "\n";
        return 2;
    }
    if (!options.load.empty()) std::snprintf(state_.worldPath.data(), state_.worldPath.size(), "%s", options.load.c_str());
    if (std::string err = openWindow(); !err.empty()) {
        std::cerr << err << "\n";
        return 2;
    }
    openSound();
    state_.pipeline = !options.noPipeline;
    simThread_.emplace();
    state_.requestResetView = true;
    {
        const View v = currentView();
        state_.windSource = windSourceAt(v, Vec2(v.width * 0.5f, v.height * 0.5f));
    }

    uint64_t limit = 0; // 0: until the window closes
    if (options.frames >= 0) limit = uint64_t(options.frames);
    else if (replaying_) limit = script_.lastFrame() + 1;
    const auto start = std::chrono::steady_clock::now();
    std::signal(SIGINT, [](int) { g_stopRequested = 1; });
    std::signal(SIGTERM, [](int) { g_stopRequested = 1; });
    if (options.frames != 0) {
        for (uint64_t f = 0;; ++f) {
            const bool closing = glfwWindowShouldClose(window_) || state_.quit || g_stopRequested;
            const bool last = closing || (limit && f + 1 >= limit);
            frame(last);
            if (last) break;
        }
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    int status = world_.finite ? 0 : 1;
    if (recording_) {
        InputScript out = recorded_;
        out.events.push_back(InputEvent{state_.frame ? state_.frame - 1 : 0, InputKind::End, 0.f, 0.f, 0});
        std::ofstream file(options.record);
        file << formatInputScript(out);
        if (!file) std::cerr << "clothtear: cannot write the input recording to '" << options.record << "'\n", status = 2;
    }
    audioOut_.close(); // the device stops before the report reads its counters
    if (!options.audioOut.empty())
        if (const std::string err = audio::writeWav(options.audioOut, soundtrack_, 2, sound_->sampleRate()); !err.empty())
            std::cerr << "clothtear: --audio-out: " << err << "\n", status = 2;
    if (!options.exportObj.empty() && !saveObj(clothMesh(world_.cloth), options.exportObj)) {
        std::cerr << "clothtear: cannot write the OBJ export to '" << options.exportObj << "'\n";
        status = 2;
    }
    if (!options.save.empty())
        if (std::string saveErr = saveWorld(world_, options.save); !saveErr.empty())
            std::cerr << "clothtear: " << saveErr << "\n", status = 2;
    if (!options.json.empty()) {
        const std::string text = report(wall).dump(2);
        if (options.json == "-") {
            std::cout << text << "\n";
        } else if (std::ofstream out(options.json); out) {
            out << text << "\n";
        } else {
            std::cerr << "clothtear: cannot write report to '" << options.json << "'\n";
            status = 2;
        }
    }
    if (lockstep_ && options.json != "-") {
        const auto& t = world_.tearLog.counts;
        std::cout << "clothtear: " << state_.frame << " frames in " << wall << " s (" << (wall > 0 ? state_.frame / wall : 0)
                  << " FPS), " << world_.cloth.particleCount() << " particles, tears " << world_.tearLog.total()
                  << " (basic " << t[0] << ", weak " << t[1] << ", one-point " << t[2] << "), balls thrown "
                  << state_.ballsThrown << ", hit cloth " << state_.ballsHitCloth << "\n";
    }
    closeWindow();
    return status;
}

// =========================================================================================== [WINDOW]

std::string App::openWindow() {
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    const std::string remedy = "run it on a virtual display with `xvfb-run -a clothtear ...`, or without a window with "
                               "`clothtear --headless ...`";
    if ((!display || !*display) && (!wayland || !*wayland))
        return "clothtear: no display to open a window on (DISPLAY is not set); " + remedy;
    glfwSetErrorCallback([](int, const char* description) { g_glfwError = description ? description : "?"; });
    if (!glfwInit()) return "clothtear: cannot use the display (" + g_glfwError + "); " + remedy;
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    window_ = glfwCreateWindow(kWindowWidth, kWindowHeight, "clothtear", nullptr, nullptr);
    if (!window_) {
        glfwTerminate();
        // The display is there but offers no OpenGL 3.3 core context (an old driver, or
        // MESA_GL_VERSION_OVERRIDE below 3.3): a virtual display with Mesa's renderer has one.
        return "clothtear: cannot open an OpenGL 3.3 core window: this display's OpenGL is older or missing (" +
               g_glfwError + "); use a driver with OpenGL 3.3 (Mesa's, e.g. `xvfb-run -a clothtear ...`), or run "
               "without a window with `clothtear --headless ...`";
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(lockstep_ ? 0 : 1);
    glewExperimental = GL_TRUE;
    if (const GLenum e = glewInit(); e != GLEW_OK) {
        const std::string why = reinterpret_cast<const char*>(glewGetErrorString(e));
        closeWindow();
        return "clothtear: cannot load OpenGL functions (" + why + ")";
    }
    while (glGetError() != GL_NO_ERROR) {
    } // glewInit may leave GL_INVALID_ENUM behind on core profiles
    if (std::string err = renderer_.init(); !err.empty()) {
        closeWindow();
        return "clothtear: " + err;
    }
    // A software renderer's raster threads (started with the context) yield to the simulation
    // thread and this one (raster_priority.h).
    const RasterNiceness niceness = rasterNicenessFromEnv(kRasterNiceness);
    if (!niceness.error.empty()) std::cerr << "clothtear: " << niceness.error << "\n";
    rasterYield_ = yieldSoftwareRaster(niceness.value);
    if (!rasterYield_.error.empty())
        std::cerr << "clothtear: " << rasterYield_.error << "; the others keep their priority\n";
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr; // the panel layout is fixed; replays must not depend on a saved file
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 4.f;
    // We feed ImGui ourselves (feedImGui), so replays drive the panel exactly as a person does.
    ImGui_ImplGlfw_InitForOpenGL(window_, false);
    ImGui_ImplOpenGL3_Init("#version 330");
    installCallbacks();
    loadBuiltInTexture(false);
    return {};
}

// The sound device: one line when there is none (no sound card, Xvfb, CI), then silence; never an
// error per frame (audio_out.h).
void App::openSound() {
    const int rate = sound_ ? sound_->sampleRate() : 48000;
    if (const std::string why = audioOut_.open(rate); !why.empty()) {
        state_.sound.status = "Silent: " + why;
        std::cerr << "clothtear: " << why << "; the app runs silently\n";
    } else {
        state_.sound.status = "Playing through SDL's " + audioOut_.driver() + " driver";
    }
}

void App::closeWindow() {
    if (!window_) return;
    if (ImGui::GetCurrentContext()) {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
    renderer_.shutdown();
    glfwDestroyWindow(window_);
    glfwTerminate();
    window_ = nullptr;
}

void App::loadBuiltInTexture(bool numbered) {
    const char* path = numbered ? CLOTHTEAR_NUMBERED_TEXTURE : CLOTHTEAR_DEFAULT_TEXTURE;
    Result<Image> img = loadImage(path);
    if (img.ok()) {
        renderer_.setTexture(img.value);
        state_.textureName = path;
    } else {
        // The build writes the PNGs; without them, make the same texture in memory.
        renderer_.setTexture(numbered ? makeFabricTexture() : makeWovenTexture());
        state_.textureName = numbered ? "built-in numbered patches (generated)" : "built-in woven fabric (generated)";
    }
}

// ============================================================================================ [FRAME]

void App::frame(bool last) {
    const double frameStart = glfwGetTime();
    glfwPollEvents();
    if (replaying_) deliverScriptEvents();
    const double now = glfwGetTime();
    const double realSeconds = now - lastTime_;
    lastTime_ = now;
    const float frameDt = world_.settings.time.frameDt;

    {
        int w = 1, h = 1;
        glfwGetWindowSize(window_, &w, &h);
        // Centre the view between the panel (left) and the stats pane (right).
        const float left = state_.showPanel ? kPanelWidth : 0.f;
        const float right = float(w) - (state_.showStats ? kStatsWidth + 8.f : 0.f);
        state_.camera.shiftX = right - left > 100.f ? std::clamp((left + right) / float(std::max(w, 1)) - 1.f, -0.6f, 0.6f) : 0.f;
    }
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    feedImGui();
    ImGuiIO& io = ImGui::GetIO();
    if (lockstep_) io.DeltaTime = frameDt; // replays see the same UI timing as the recording
    ImGui::NewFrame();
    const bool uiMouse = io.WantCaptureMouse, uiKeyboard = io.WantCaptureKeyboard;

    handleEvents(uiMouse, uiKeyboard);
    handleContinuous(lockstep_ ? frameDt : float(realSeconds), uiKeyboard);
    drawControlPanel(state_, world_);
    drawStatsPane(state_, world_);
    drawTimeline(state_, rewind_);
    drawHelpOverlay(state_);
    serveRequests();
    // The pipeline: the steps of this frame run on the simulation thread while the main thread draws
    // the world as the last frame left it (one frame later on screen). The renderer reads the world
    // only in prepare(): GL copies what it uploads, so the thread may step the world once prepare()
    // returned, while submit() issues the draws. The steps see the same input on the same state
    // either way (this frame's events were handled above, on the state the last frame's steps
    // left), so a replay gives the same world. The last frame steps first: its screenshot and
    // report show the final state.
    const int steps = stepsThisFrame(realSeconds);
    const bool overlap = state_.pipeline && steps > 0 && !last && !state_.requestExportObj;
    if (!overlap) runSteps(steps);

    const View view = currentView();
    drawToolHud(state_, world_, view, input_.mouseX, input_.mouseY, uiMouse);
    ImGui::Render();
    if (state_.requestExportObj) {
        state_.requestExportObj = false;
        const std::string name = "clothtear-" + std::to_string(state_.frame) + ".obj";
        state_.say(saveObj(clothMesh(world_.cloth), name) ? "Exported the cloth to " + name
                                                          : "Cannot write " + name + "; nothing exported");
    }
    const double drawStart = glfwGetTime();
    int fbWidth = 0, fbHeight = 0;
    glfwGetFramebufferSize(window_, &fbWidth, &fbHeight);
    renderer_.prepare(world_, state_.render, view);
    // From here until simThread_.wait() the world, the tools' drag state, the history and the sound
    // stream are the simulation thread's (sim_thread.h): nothing below reads them.
    const double stepsStart = glfwGetTime();
    if (overlap) simThread_->start([this, steps] { runSteps(steps); });
    renderer_.submit(fbWidth, fbHeight);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    const double drawEnd = glfwGetTime();
    if (last && !options_.screenshot.empty())
        if (std::string err = writeScreenshot(options_.screenshot); !err.empty()) std::cerr << "clothtear: " << err << "\n";
    std::string screenshotSaid;
    if (state_.requestScreenshot) {
        state_.requestScreenshot = false;
        const std::string name = "clothtear-" + std::to_string(state_.frame) + ".png";
        const std::string err = writeScreenshot(name);
        screenshotSaid = err.empty() ? "Saved " + name : err;
    }
    glfwSwapBuffers(window_);
    const double swapEnd = glfwGetTime();
    if (overlap) simThread_->wait();
    const double waitEnd = glfwGetTime();
    afterSteps();
    if (!screenshotSaid.empty()) state_.say(screenshotSaid);
    audioOut_.setMuted(state_.sound.muted);
    audioOut_.setVolume(state_.sound.volume);
    state_.stats.drawMs = 0.9 * state_.stats.drawMs + 0.1 * 1000.0 * (drawEnd - drawStart);
    state_.stats.swapMs = 0.9 * state_.stats.swapMs + 0.1 * 1000.0 * (swapEnd - drawEnd);
    RunCosts& run = state_.runCosts;
    run.drawMs += 1000.0 * (drawEnd - drawStart);
    run.swapMs += 1000.0 * (swapEnd - drawEnd);
    run.waitMs += 1000.0 * (waitEnd - swapEnd);
    state_.stats.clothTrianglesDrawn = renderer_.clothTriangles();
    input_.endFrame();
    updateStats(now);
    state_.frame++;
    const double end = glfwGetTime();
    run.serialMs += 1000.0 * (overlap ? (stepsStart - frameStart) + (end - waitEnd) : end - frameStart);
}

// ========================================================================================= [REQUESTS]

void App::serveRequests() {
    // A setup picked keeps the current mesh; a mesh loaded keeps the current setup.
    auto current = [&] {
        Result<SceneName> parsed = parseSceneName(state_.scene);
        return parsed.ok() ? parsed.value : SceneName{findScene("curtain"), {}};
    };
    if (state_.requestScene >= 0) {
        const auto scenes = allScenes();
        if (state_.requestScene < int(scenes.size())) {
            const std::string err =
                loadScene(composeSceneName(scenes[state_.requestScene].name, current().objPath), false);
            state_.say(err.empty() ? withWarnings(std::string("Scene: ") + scenes[state_.requestScene].description) : err);
            if (err.empty()) state_.requestResetView = true;
        }
        state_.requestScene = -1;
    }
    if (state_.requestLoadMesh || state_.requestBuiltInMesh) {
        const std::string setup = current().setup->name;
        const std::string path = state_.requestLoadMesh ? std::string(state_.meshPath.data()) : std::string();
        std::string err = state_.requestLoadMesh && path.empty() ? "no OBJ path given" : "";
        if (err.empty()) err = loadScene(composeSceneName(setup, path), false);
        state_.meshError = err.empty() ? std::string() : err + "; keeping the current cloth";
        if (err.empty()) {
            state_.requestResetView = true;
            state_.say(withWarnings(path.empty() ? setup + " on its built-in mesh" : setup + " on " + path));
        }
        state_.requestLoadMesh = state_.requestBuiltInMesh = false;
    }
    if (state_.requestDefaults) {
        state_.requestDefaults = false;
        const std::string err = loadScene(state_.scene, false);
        state_.say(err.empty() ? "Parameters back to the defaults of " + state_.scene : err);
    }
    if (state_.requestReset) {
        state_.requestReset = false;
        rebuildWorld();
    }
    if (state_.requestSaveWorld || state_.requestLoadWorld) serveWorldFile();
    if (state_.requestResetView) {
        state_.requestResetView = false;
        frameWorld(state_.camera, world_);
    }
    if (state_.requestLoadTexture) {
        state_.requestLoadTexture = false;
        const std::string path(state_.texturePath.data());
        Result<Image> img = loadImage(path);
        if (img.ok()) {
            renderer_.setTexture(img.value);
            state_.textureName = path;
            state_.textureError.clear();
        } else {
            state_.textureError = img.error + "; keeping the current texture";
        }
    }
    if (state_.requestUndo || state_.requestRedo) {
        const bool undo = state_.requestUndo;
        state_.requestUndo = state_.requestRedo = false;
        const std::string said = undo ? rewind_.undo(world_) : rewind_.redo(world_);
        if (said.empty()) state_.say(undo ? "Nothing to undo" : "Nothing to redo");
        else afterRestore(said);
    }
    if (state_.requestDeletePiece >= 0) {
        if (state_.drag.active()) releaseDrag(world_, state_.drag, false); // its particles are renumbered
        rewind_.beforeEdit(world_, "the deletion of a piece");
        const size_t removed = world_.deletePiece(Index(state_.requestDeletePiece));
        state_.requestDeletePiece = -1;
        state_.say("Deleted a piece of " + std::to_string(removed) + " triangles (Ctrl+Z brings it back)");
    }
    if (state_.requestView >= 0) {
        rewind_.view(world_, size_t(state_.requestView));
        state_.requestView = -1;
        state_.paused = true; // a frame of the past is shown until P resumes from it
        afterRestore({});
    }
    if (state_.requestDefaultTexture || state_.requestNumberedTexture) {
        state_.textureError.clear();
        loadBuiltInTexture(state_.requestNumberedTexture);
        state_.requestDefaultTexture = state_.requestNumberedTexture = false;
    }
}

// The panel's world file row: Save writes the world as it is; Load replaces it, or says in red why
// not and keeps the current one.
void App::serveWorldFile() {
    const std::string path(state_.worldPath.data());
    std::string err = path.empty() ? "no world file path given" : "";
    if (err.empty() && state_.requestSaveWorld) err = saveWorld(world_, path);
    if (err.empty() && state_.requestLoadWorld) {
        err = loadWorldFile(path, false);
        if (!err.empty()) err += "; keeping the current cloth";
        else state_.requestResetView = true;
    }
    state_.worldError = err;
    if (err.empty())
        state_.say(state_.requestSaveWorld ? "Saved the world to " + path
                                           : withWarnings("Loaded " + path + " at t = " + std::to_string(world_.time) + " s"));
    state_.requestSaveWorld = state_.requestLoadWorld = false;
}

// =========================================================================================== [OUTPUT]

std::string App::writeScreenshot(const std::string& path) {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    Image img;
    img.width = w;
    img.height = h;
    img.rgba.resize(size_t(w) * h * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
    // GL rows start at the bottom; PNG rows at the top.
    const size_t row = size_t(w) * 4;
    std::vector<uint8_t> tmp(row);
    for (int y = 0; y < h / 2; ++y) {
        uint8_t* a = &img.rgba[size_t(y) * row];
        uint8_t* b = &img.rgba[size_t(h - 1 - y) * row];
        std::copy_n(a, row, tmp.data());
        std::copy_n(b, row, a);
        std::copy_n(tmp.data(), row, b);
    }
    for (size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 255;
    return savePng(path, img);
}

// Per frame over the whole run (its app.frames frames: draw, swap, the wait for the simulation
// thread, the frame itself) and per world.step() (step_ms: wall-clock, on the simulation thread). The report's draw_ms, swap_ms
// and step_ms are the stats pane's smoothed figures of the last frames.
nlohmann::json App::meanCosts(double wallSeconds) const {
    const RunCosts& run = state_.runCosts;
    const double frames = double(state_.frame), steps = double(state_.clock.stepsTimed);
    auto per = [](double total, double count) { return count > 0 ? total / count : 0.0; };
    return {
        {"frame_ms", per(1000.0 * wallSeconds, frames)},
        {"draw_ms", per(run.drawMs, frames)},
        {"swap_ms", per(run.swapMs, frames)},
        {"wait_ms", per(run.waitMs, frames)},
        {"steps_ms", per(run.stepsMs, frames)},
        {"serial_ms", per(run.serialMs, frames)},
        {"steps", state_.clock.stepsTimed},
        {"step_ms", per(state_.clock.stepMsTotal, steps)},
    };
}

nlohmann::json App::report(double wallSeconds) const {
    nlohmann::json r = makeReport(world_, state_.scene, wallSeconds);
    if (!loaded_.is_null()) r["loaded"] = loaded_;
    nlohmann::json settings = nlohmann::json::object();
    for (const ParamInfo& p : allParams()) settings[p.name] = formatParamValue(world_.settings, p);
    r["settings"] = settings;
    r["app"] = {
        {"frames", state_.frame},
        {"fps", wallSeconds > 0 ? double(state_.frame) / wallSeconds : 0.0},
        {"lockstep", lockstep_},
        {"paused", state_.paused},
        {"tool", toolName(state_.tool)},
        {"balls_thrown", state_.ballsThrown},
        {"balls_hit_cloth", state_.ballsHitCloth},
        {"script_events", script_.events.size()},
        {"topology_uploads", renderer_.topologyUploads()},
        {"torn_edges", renderer_.tornEdges()}, // drawn with loose threads (render_mesh.h findTornEdges)
        {"cloth_triangles_drawn", renderer_.clothTriangles()}, // last frame; fewer from far (render_lod.h)
        {"stats_pane_overflow_px", state_.stats.statsOverflowPx}, // the stats pane's widest row past its edge
        {"dynamic_uploads", renderer_.dynamicUploads()}, // frames whose positions and normals were uploaded
        {"raster_threads_yielding", rasterYield_.threads}, // llvmpipe's, lowered (raster_priority.h)
        {"raster_niceness", rasterYield_.niceness},
        {"draw_ms", state_.stats.drawMs},
        {"swap_ms", state_.stats.swapMs},
        {"step_ms", state_.clock.stepCostMs},
        {"mean", meanCosts(wallSeconds)},
        {"texture", state_.textureName},
        {"texture_error", state_.textureError},
        {"mesh_error", state_.meshError},
        {"world_file", state_.worldFile},
        {"world_error", state_.worldError},
    };
    const AudioOutCounters sound = audioOut_.counters();
    r["app"]["audio"] = {
        {"device", audioOut_.driver()}, // SDL's driver while it played, "" without a device
        {"status", state_.sound.status},
        {"muted", state_.sound.muted},
        {"volume", state_.sound.volume},
        {"pushed", sound.pushed}, // stereo frames handed to the device's queue
        {"dropped", sound.dropped},
        {"played", sound.played},
        {"underrun", sound.underrun},
        {"callbacks", sound.callbacks},
    };
    if (!options_.audioOut.empty() && sound_)
        r["audio"] = {{"file", options_.audioOut},
                      {"seconds", double(soundtrack_.size() / 2) / sound_->sampleRate()},
                      {"samples", soundtrack_.size() / 2}, // stereo frames
                      {"sample_rate", sound_->sampleRate()},
                      {"grains", sound_->synth().grains()}};
    const History& h = rewind_.history();
    r["app"]["history"] = {
        {"checkpoints", h.size()},
        {"seconds", h.size() ? h.at(h.size() - 1).time() - h.at(0).time() : 0.0},
        {"bytes", h.bytes()},
        {"undo", rewind_.undoCount()},
        {"redo", rewind_.redoCount()},
        {"viewing", rewind_.viewing()},
    };
    return r;
}

} // namespace clothtear::app
