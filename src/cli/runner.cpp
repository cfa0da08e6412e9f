// Headless runner: parse, load the scene, step, report.
#include "runner.h"

#include "clothtear/config_file.h"
#include "clothtear/params.h"
#include "clothtear/scenes.h"
#include "clothtear/state_hash.h"

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>

namespace clothtear {

int parseCommandLine(int argc, char** argv, CliOptions& o, bool appAvailable) {
    CLI::App app{"clothtear: interactive cloth tearing (Onal 2013) and its headless runner"};
    app.add_flag("--headless", o.headless, "Run without a window and print/write a report");
    app.add_option("--scene", o.scene, "Scene name (see --list-scenes) or obj:PATH");
    app.add_option("--seconds", o.seconds, "Simulated seconds to run (headless)")
        ->check(CLI::Number) // "not a number" before "not in range" for text
        ->check(CLI::Range(0.0, 1e6));
    app.add_option("--set", o.sets, "Set a parameter: --set key=value (repeatable; see --list-params)");
    app.add_option("--config", o.config, "Read the scene and parameters from FILE ('key = value' lines, # comments)");
    app.add_option("--json", o.json, "Write the JSON report to FILE ('-' for stdout)");
    app.add_flag("--list-scenes", o.listScenes, "List the scenes and exit");
    app.add_flag("--list-params", o.listParams, "List every parameter with default, unit and range, and exit");
    app.add_flag("--version", o.version, "Print the version and exit");
    if (appAvailable) {
        app.add_option("--frames", o.frames, "App: run N frames, then exit")->check(CLI::Number)->check(CLI::Range(0, 100000000));
        app.add_option("--screenshot", o.screenshot, "App: write a PNG of the last frame to FILE");
        app.add_option("--script", o.script, "App: replay an input script");
        app.add_option("--record", o.record, "App: record input to a script file");
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        std::cout << app.help();
        return 0;
    } catch (const CLI::ParseError& e) {
        std::cerr << "clothtear: " << e.what() << " (see --help)\n";
        return 2;
    }
    if (o.version) {
        std::cout << "clothtear " << CLOTHTEAR_VERSION << "\n";
        return 0;
    }
    if (o.listScenes) {
        for (const SceneDef& s : allScenes()) std::cout << s.name << "\t" << s.description << "\n";
        std::cout << "obj:PATH\tCurtain made from an OBJ file (v, vt, f)\n";
        return 0;
    }
    if (o.listParams) {
        std::cout << paramsMarkdown();
        return 0;
    }
    // The window app's options mean nothing without a window: refuse them rather than ignore them.
    if (o.headless)
        for (const char* option : {"--frames", "--screenshot", "--script", "--record"})
            if (appAvailable && app.count(option)) {
                std::cerr << "clothtear: " << option << " needs the window app; drop --headless (no display: "
                          << "xvfb-run -a clothtear ...)\n";
                return 2;
            }
    // The config file comes first: --scene and --set on the command line win over it.
    if (app.count("--config")) {
        Result<ConfigFile> config = loadConfig(o.config);
        if (!config.ok()) {
            std::cerr << "clothtear: " << config.error << "\n";
            return 2;
        }
        if (!config.value.scene.empty() && !app.count("--scene")) o.scene = config.value.scene;
        o.sets.insert(o.sets.begin(), config.value.assignments.begin(), config.value.assignments.end());
    }
    // Check every --set now, so bad input fails before any work with one clear message.
    Settings probe;
    for (const std::string& s : o.sets)
        if (std::string err = applyAssignment(probe, s); !err.empty()) {
            std::cerr << "clothtear: --set " << s << ": " << err << "\n";
            return 2;
        }
    return -1;
}

nlohmann::json makeReport(const World& w, const std::string& scene, double wallSeconds) {
    using nlohmann::json;
    const Cloth& c = w.cloth;
    json phases = json::object();
    for (int p = 0; p < int(Phase::Count); ++p) {
        const double perStep = w.steps ? w.profile.ms[p] / double(w.steps) : 0.0;
        phases[phaseName(Phase(p))] = {{"ms_per_step", perStep}, {"runs", w.profile.runs[p]}};
    }
    double totalMs = 0;
    for (double ms : w.profile.ms) totalMs += ms;
    json tears = json::object();
    for (int m = 0; m < int(TearMode::Count); ++m) tears[tearModeName(TearMode(m))] = w.tearLog.counts[m];
    json events = json::array();
    for (const TearEvent& e : w.tearLog.events)
        events.push_back({{"mode", tearModeName(e.mode)},
                          {"time", e.time},
                          {"rest", {e.restPos.x(), e.restPos.y(), e.restPos.z()}},
                          {"uv", {e.uv.x(), e.uv.y()}},
                          {"strain", e.strain}});
    uint64_t pinned = 0, weak = 0;
    for (uint8_t f : c.flags) pinned += (f & kPinned) != 0, weak += (f & kWeak) != 0;
    json balls = json::array();
    for (const Ball& b : w.balls)
        balls.push_back({{"x", {b.x.x(), b.x.y(), b.x.z()}}, {"v", {b.v.x(), b.v.y(), b.v.z()}}, {"radius", b.radius}});
    double minY = 1e30, maxY = -1e30;
    for (const Vec3& x : c.x) minY = std::min<double>(minY, x.y()), maxY = std::max<double>(maxY, x.y());
    return json{
        {"scene", scene},
        {"seconds", w.time},
        {"steps", w.steps},
        {"substeps", w.settings.time.substeps},
        {"frame_substeps", w.frameSubsteps}, // after the stability guard (time.max_substeps)
        {"dt", double(w.settings.time.frameDt) / w.settings.time.substeps},
        {"integrator", formatParamValue(w.settings, *findParam("time.integrator"))},
        {"particles", c.particleCount()},
        {"pinned", pinned},
        {"weak_points", weak},
        {"springs", c.springs.size()},
        {"bend_springs", c.bends.size()},
        {"triangles", c.triangles.size()},
        {"total_mass", c.totalMass()},
        {"rest_area", c.totalRestArea()},
        {"uv_area", c.totalUvArea()},
        {"max_strain", w.maxStrain},
        {"min_y", minY},
        {"max_y", maxY},
        {"kinetic_energy", w.kineticEnergy()},
        {"finite", w.finite},
        {"state_hash", hashHex(stateHash(w))}, // bit-identical runs give the same hash (state_hash.h)
        {"non_finite_where", w.nonFiniteWhere},
        {"ms_per_step", w.steps ? totalMs / double(w.steps) : 0.0},
        {"wall_seconds", wallSeconds},
        {"phases", phases},
        // Sub-steps whose length limit was still correcting at its last pass, and those springs.
        {"limit_capped_substeps", w.profile.limitCapped},
        {"limit_capped_springs", w.profile.limitCappedSprings},
        {"substeps_run", w.profile.substeps},
        {"tears", tears},
        {"tears_total", w.tearLog.total()},
        {"tear_events", events},
        {"validation_error", w.tearLog.validationError}, // first invariant violation (tear.validate=1)
        {"balls", balls},
    };
}

int runHeadless(const CliOptions& o) {
    World world;
    if (std::string err = loadScene(world, o.scene, o.sets); !err.empty()) {
        std::cerr << "clothtear: " << err << "\n";
        return 2;
    }
    const long frames = std::lround(o.seconds / world.settings.time.frameDt);
    const auto start = std::chrono::steady_clock::now();
    for (long f = 0; f < frames; ++f) world.step();
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const nlohmann::json report = makeReport(world, o.scene, wall);
    if (o.json == "-") {
        std::cout << report.dump(2) << "\n";
    } else if (!o.json.empty()) {
        std::ofstream out(o.json);
        if (!out) {
            std::cerr << "clothtear: cannot write report to '" << o.json << "'\n";
            return 2;
        }
        out << report.dump(2) << "\n";
    } else {
        std::cout << o.scene << ": " << world.steps << " frames, " << world.cloth.particleCount() << " particles, "
                  << world.cloth.triangles.size() << " triangles, max strain " << world.maxStrain << ", tears "
                  << world.tearLog.total() << ", " << report["ms_per_step"].get<double>() << " ms/frame, "
                  << (world.finite ? "finite" : "NON-FINITE") << "\n";
    }
    return world.finite ? 0 : 1;
}

} // namespace clothtear
