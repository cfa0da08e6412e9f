// The simulation side of the app: scenes, rebuilds, the fixed-step loop and the stats.
#include "app.h"

#include "runner.h"

#include "clothtear/scenes.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace clothtear::app {

std::string App::loadScene(const std::string& name, bool withOverrides) {
    const std::vector<std::string> none;
    // clothtear::loadScene leaves the world as it was on error.
    if (std::string err = clothtear::loadScene(world_, name, withOverrides ? state_.overrides : none); !err.empty())
        return err;
    state_.scene = name;
    if (const Result<SceneName> parsed = parseSceneName(name); parsed.ok() && !parsed.value.objPath.empty()) {
        const std::string& path = parsed.value.objPath;
        std::snprintf(state_.meshPath.data(), state_.meshPath.size(), "%s", path.c_str());
    }
    state_.say(withWarnings({}));
    startedAnew();
    return {};
}

std::string App::loadWorldFile(const std::string& path, bool withOverrides) {
    const std::vector<std::string> none;
    // clothtear::loadWorldFile leaves the world as it was on error.
    if (std::string err = clothtear::loadWorldFile(world_, path, withOverrides ? state_.overrides : none); !err.empty())
        return err;
    state_.worldFile = path;
    loaded_ = loadedReport(path, world_);
    startedAnew();
    return {};
}

void App::startedAnew() {
    // New particles: a held particle index would now mean another one.
    state_.drag = DragState{};
    state_.windBlowing = false;
    state_.ballFlags.assign(world_.balls.size(), 0);
    state_.clock.reset();
    state_.stats.sampleStart = -1;
    rewind_.restart(world_); // a new world: its own history (rewind.h)
    renderer_.invalidateTopology(); // a new world: draw it anew, whatever its counters say
    if (sound_) sound_->rebase(world_); // its tears so far are not heard; the stream goes on
    else sound_.emplace(world_);
}

void App::rebuildWorld() {
    if (std::string err = world_.rebuild(); !err.empty()) {
        state_.drag = DragState{};
        state_.windBlowing = false;
        state_.say("Rebuild failed: " + err);
        return;
    }
    if (Result<SceneName> scene = parseSceneName(state_.scene); scene.ok()) scene.value.setup->populate(world_);
    startedAnew();
    state_.say(withWarnings({})); // a pin mode that pins every particle is worth a word
}

std::string App::withWarnings(std::string message) const {
    const std::string warning = sceneWarnings(world_);
    if (warning.empty()) return message;
    return message.empty() ? "Warning: " + warning : message + " (warning: " + warning + ")";
}

int App::stepsThisFrame(double realSeconds) {
    if (state_.paused) {
        state_.clock.reset();
        if (state_.stepRequests > 0) return state_.stepRequests--, 1;
        return 0;
    }
    if (lockstep_) return 1;
    return state_.clock.advance(realSeconds, world_.settings.time.frameDt);
}

void App::runSteps(int steps) {
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < steps && world_.finite; ++i) stepOnce();
    const std::chrono::duration<double, std::milli> took = std::chrono::steady_clock::now() - start;
    state_.runCosts.stepsMs += took.count();
}

void App::afterSteps() {
    // A blown-up state only gets slower to step (NaN springs tear without end): stop and say so.
    if (!world_.finite && !state_.paused) {
        state_.paused = true;
        state_.say("The simulation blew up (" + world_.nonFiniteWhere + "): paused. R resets the cloth; " +
                   "Defaults restores safe parameters.");
    }
}

void App::stepOnce() {
    const size_t particlesBefore = world_.cloth.particleCount();
    const size_t pushed = dragBeforeStep(world_, state_.drag, state_.tools.maxDragSpeed);
    if (state_.tools.windFixed || (state_.windBlowing && state_.tool == Tool::Wind))
        applyWind(world_, state_.windSource, state_.tools.radiusPx, state_.tools.windPressure,
                  world_.settings.time.frameDt);
    applyDueCuts(world_, options_.cuts, nextCut_); // --cut strokes whose time has come
    const auto start = std::chrono::steady_clock::now();
    world_.step();
    state_.clock.reportStepCost(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    dragAfterStep(world_, state_.drag, pushed, particlesBefore);
    trackBalls();
    rewind_.afterStep(world_);
    feedSound();
}

void App::feedSound() {
    const bool keep = !options_.audioOut.empty();
    if (!sound_ || (!audioOut_.isOpen() && !keep)) return; // nobody listens
    soundBlock_.clear();
    const size_t frames = sound_->afterFrame(world_, soundBlock_);
    audioOut_.push(soundBlock_.data(), frames); // never waits (audio_out.h)
    if (keep) soundtrack_.insert(soundtrack_.end(), soundBlock_.begin(), soundBlock_.end());
}

void App::afterRestore(const std::string& message) {
    state_.drag = DragState{}; // the restored pins are the world's own: nothing to give back
    knifeEnd(state_.knife);
    state_.windBlowing = false;
    state_.ballFlags.assign(world_.balls.size(), kBallThrown | kBallTouched);
    state_.pieces = PiecesSummary{};
    renderer_.invalidateTopology();
    state_.clock.reset();
    if (sound_) sound_->rebase(world_); // the restored past's tears are not heard twice
    if (!message.empty()) state_.say(message);
}

// A thrown ball "hit the cloth" once any particle came within its radius plus a small margin.
void App::trackBalls() {
    state_.ballFlags.resize(world_.balls.size(), 0);
    const float margin = std::max(0.03f, 2.f * world_.settings.collision.thickness);
    for (size_t i = 0; i < world_.balls.size(); ++i) {
        uint8_t& f = state_.ballFlags[i];
        if (!(f & kBallThrown) || (f & kBallTouched)) continue;
        const Ball& b = world_.balls[i];
        const float r2 = (b.radius + margin) * (b.radius + margin);
        for (const Vec3& x : world_.cloth.x)
            if ((x - b.x).squaredNorm() < r2) {
                f |= kBallTouched;
                state_.ballsHitCloth++;
                break;
            }
    }
}

void App::updateStats(double now) {
    Stats& s = state_.stats;
    auto sampleEnergies = [&] {
        s.kineticEnergy = world_.kineticEnergy();
        s.potentialEnergy = world_.potentialEnergy();
    };
    if (s.sampleStart < 0 || world_.steps < s.stepsAtStart) {
        sampleEnergies();
        s.sampleStart = now;
        s.frames = 0;
        s.profileAtStart = world_.profile;
        s.stepsAtStart = world_.steps;
        return;
    }
    s.frames++;
    const double elapsed = now - s.sampleStart;
    if (elapsed < 0.5) return;
    const uint64_t steps = world_.steps - s.stepsAtStart;
    s.fps = s.frames / elapsed;
    s.simFps = double(steps) / elapsed;
    double total = 0;
    for (int p = 0; p < int(Phase::Count); ++p) {
        s.phaseMs[p] = steps ? (world_.profile.ms[p] - s.profileAtStart.ms[p]) / double(steps) : 0.0;
        total += s.phaseMs[p];
    }
    s.msPerStep = total;
    sampleEnergies();
    const uint64_t substeps = world_.profile.substeps - s.profileAtStart.substeps;
    s.limitCappedShare =
        substeps ? double(world_.profile.limitCapped - s.profileAtStart.limitCapped) / double(substeps) : 0.0;
    s.sampleStart = now;
    s.frames = 0;
    s.profileAtStart = world_.profile;
    s.stepsAtStart = world_.steps;
}

} // namespace clothtear::app
