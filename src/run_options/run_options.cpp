// Run options (run_options.h): parse, answer the informational flags, fold the config file, check --set.
#include "run_options.h"

#include "clothtear/config_file.h"
#include "clothtear/knife.h"
#include "clothtear/params.h"
#include "clothtear/scenes.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iostream>

namespace clothtear {
namespace {

// A plain decimal number ("nan" and "inf" pass here and are refused by checkStroke, which says so).
bool number(std::string_view text, double& out) {
    while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
    while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return !text.empty() && ec == std::errc() && end == text.data() + text.size();
}

} // namespace

Result<CutRequest> parseCut(const std::string& text) {
    CutRequest cut;
    cut.text = text;
    std::string_view points = text;
    if (const size_t colon = points.find(':'); colon != std::string_view::npos) {
        const std::string_view t = points.substr(0, colon);
        if (!number(t, cut.time) || !std::isfinite(cut.time) || cut.time < 0)
            return Result<CutRequest>::failure("'" + std::string(t) + "' is not a time in seconds (>= 0) before ':'");
        points.remove_prefix(colon + 1);
    }
    for (size_t k = 1; !points.empty() || k == 1; ++k) {
        const size_t semi = points.find(';');
        const std::string_view point = points.substr(0, semi);
        points = semi == std::string_view::npos ? std::string_view() : points.substr(semi + 1);
        const size_t comma = point.find(',');
        Vec2d p;
        if (comma == std::string_view::npos || point.find(',', comma + 1) != std::string_view::npos)
            return Result<CutRequest>::failure("point " + std::to_string(k) + " '" + std::string(point) +
                                               "' is not two numbers U,V");
        for (int i = 0; i < 2; ++i) {
            const std::string_view v = i == 0 ? point.substr(0, comma) : point.substr(comma + 1);
            if (!number(v, p[i]))
                return Result<CutRequest>::failure("point " + std::to_string(k) + ": '" + std::string(v) +
                                                   "' is not a number");
        }
        cut.stroke.push_back(p);
    }
    if (std::string err = checkStroke(cut.stroke); !err.empty()) return Result<CutRequest>::failure(err);
    Result<CutRequest> r;
    r.value = std::move(cut);
    return r;
}

int parseCommandLine(CLI::App& app, int argc, char** argv, const char* program) {
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp&) {
        std::cout << app.help();
        return 0;
    } catch (const CLI::ParseError& e) {
        std::cerr << program << ": " << e.what() << " (see --help)\n";
        return 2;
    }
    return -1;
}

namespace {

// --load: the world file holds the scene, so naming one too is refused rather than one of them
// ignored; --set applies on top of the file's parameters (checked as always), except those that
// rebuild the cloth, which would throw the loaded cloth away.
std::string checkLoadOptions(const CLI::App& app, const RunOptions& o, bool configScene) {
    for (const char* option : {"--scene", "--mesh"})
        if (app.count(option))
            return std::string("--load and ") + option + ": the world file holds the scene and its cloth; give one of them";
    if (configScene) return "--load and a config file with a scene line (" + o.config + "): the world file holds the scene; give one of them";
    Settings probe;
    for (const std::string& s : o.sets) {
        if (std::string err = applyAssignment(probe, s); !err.empty()) return "--set " + s + ": " + err;
        std::string_view key = std::string_view(s).substr(0, s.find('='));
        while (!key.empty() && (key.front() == ' ' || key.front() == '\t')) key.remove_prefix(1);
        while (!key.empty() && (key.back() == ' ' || key.back() == '\t')) key.remove_suffix(1);
        const ParamInfo* p = findParam(key);
        if (p && p->rebuildsCloth)
            return "--set " + s + ": " + p->name + " rebuilds the cloth, which would replace the loaded one; not with --load";
    }
    return {};
}

} // namespace

int parseRunOptions(int argc, char** argv, RunOptions& o, const RunOptionsExtension& extension) {
    CLI::App app{"clothtear: interactive cloth tearing (Onal 2013) and its headless runner"};
    app.add_flag("--headless", o.headless, "Run without a window and print/write a report");
    app.add_option("--scene", o.scene, "Scene name (see --list-scenes), obj:PATH or SCENE:obj:PATH");
    std::string mesh;
    app.add_option("--mesh", mesh, "Run the scene on the OBJ mesh FILE (the same as --scene SCENE:obj:FILE)");
    app.add_option("--seconds", o.seconds, "Simulated seconds to run (headless)")
        ->check(CLI::Number) // "not a number" before "not in range" for text
        ->check(CLI::Range(0.0, 1e6));
    app.add_option("--set", o.sets, "Set a parameter: --set key=value (repeatable; see --list-params)");
    app.add_option("--config", o.config, "Read the scene and parameters from FILE ('key = value' lines, # comments)");
    app.add_option("--json", o.json, "Write the JSON report to FILE ('-' for stdout)");
    app.add_option("--export-obj", o.exportObj, "At the end, write the cloth as it is (torn) to FILE as OBJ with UVs");
    app.add_option("--load", o.load,
                   "Start from the world file FILE (saved with --save or the panel) instead of building a scene; "
                   "--set applies on top, except parameters that rebuild the cloth");
    app.add_option("--save", o.save, "At the end, write the whole world to FILE (a world file --load continues exactly)");
    std::vector<std::string> cuts;
    app.add_option("--cut", cuts,
                   "Cut the cloth with the knife along U,V;U,V;... (metres in the mesh's own plane from its middle, "
                   "U right, V up), at T seconds with a T: prefix (repeatable; quote the ';')");
    app.add_option("--audio-out", o.audioOut, "Write the sound of the run's tears to FILE (WAV, 48 kHz stereo float; the window app writes what it played, at full volume)");
    app.add_flag("--list-scenes", o.listScenes, "List the scenes and exit");
    app.add_flag("--list-params", o.listParams, "List every parameter with default, unit and range, and exit");
    app.add_flag("--version", o.version, "Print the version and exit");
    if (extension.add) extension.add(app);
    if (const int status = parseCommandLine(app, argc, argv, "clothtear"); status >= 0) return status;
    if (o.version) {
        std::cout << "clothtear " << CLOTHTEAR_VERSION << "\n";
        return 0;
    }
    if (o.listScenes) {
        for (const SceneDef& s : allScenes()) std::cout << s.name << "\t" << s.description << "\n";
        std::cout << "obj:PATH\tCurtain made from an OBJ file (v, vt, f)\n"
                  << "SCENE:obj:PATH\tAny scene above on an OBJ mesh (or --scene SCENE --mesh PATH)\n";
        return 0;
    }
    if (o.listParams) {
        std::cout << paramsMarkdown();
        return 0;
    }
    if (extension.check)
        if (std::string refused = extension.check(app, o); !refused.empty()) {
            std::cerr << "clothtear: " << refused << "\n";
            return 2;
        }
    // The config file comes first: --scene and --set on the command line win over it.
    bool configScene = false;
    if (app.count("--config")) {
        Result<ConfigFile> config = loadConfig(o.config);
        if (!config.ok()) {
            std::cerr << "clothtear: " << config.error << "\n";
            return 2;
        }
        configScene = !config.value.scene.empty();
        if (configScene && !app.count("--scene")) o.scene = config.value.scene;
        o.sets.insert(o.sets.begin(), config.value.assignments.begin(), config.value.assignments.end());
    }
    if (!mesh.empty()) {
        Result<SceneName> scene = parseSceneName(o.scene);
        if (!scene.ok()) {
            std::cerr << "clothtear: --scene " << o.scene << ": " << scene.error << "\n";
            return 2;
        }
        o.scene = composeSceneName(scene.value.setup->name, mesh);
    }
    // An export, a save or a soundtrack that cannot be written is refused before the run, not after it.
    for (const auto& [option, path] : {std::pair{"--export-obj", &o.exportObj}, std::pair{"--save", &o.save},
                                       std::pair{"--audio-out", &o.audioOut}})
        if (!path->empty() && !std::ofstream(*path, std::ios::app)) {
            std::cerr << "clothtear: " << option << ": cannot write '" << *path << "'\n";
            return 2;
        }
    if (!o.load.empty()) {
        if (std::string refused = checkLoadOptions(app, o, configScene); !refused.empty()) {
            std::cerr << "clothtear: " << refused << "\n";
            return 2;
        }
        return -1; // the world file is read by whoever runs it: one line and status 2 if it is bad
    }
    if (Result<SceneName> scene = parseSceneName(o.scene); !scene.ok()) {
        std::cerr << "clothtear: --scene: " << scene.error << "\n";
        return 2;
    }
    for (const std::string& text : cuts) {
        Result<CutRequest> cut = parseCut(text);
        if (!cut.ok()) {
            std::cerr << "clothtear: --cut '" << text << "': " << cut.error << "\n";
            return 2;
        }
        // A headless run ends at --seconds: a cut after that would silently never happen.
        if (o.headless && cut.value.time > o.seconds) {
            std::cerr << "clothtear: --cut '" << text << "': at " << cut.value.time << " s, after the end of the run (--seconds "
                      << o.seconds << ")\n";
            return 2;
        }
        o.cuts.push_back(std::move(cut.value));
    }
    std::stable_sort(o.cuts.begin(), o.cuts.end(), [](const CutRequest& a, const CutRequest& b) { return a.time < b.time; });
    // Check every --set now, so bad input fails before any work with one clear message.
    Settings probe;
    for (const std::string& s : o.sets)
        if (std::string err = applyAssignment(probe, s); !err.empty()) {
            std::cerr << "clothtear: --set " << s << ": " << err << "\n";
            return 2;
        }
    return -1;
}

} // namespace clothtear
