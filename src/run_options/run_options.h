// Run options: the command line every `clothtear` shares, with or without the window app.
//
//   --headless --scene NAME --mesh OBJ --seconds S --export-obj FILE --audio-out FILE --set key=value --config FILE --json FILE
//   --load FILE --save FILE --cut [T:]U,V;U,V;... --list-scenes --list-params --version --help
//
// parseRunOptions reads them with CLI11, answers --help, --version and the lists, folds the config
// file in (the command line wins over it) and checks every --set, so bad input fails before any work
// with one clear line. A front end with options of its own (the window app: src/app/app_options.h)
// registers them through RunOptionsExtension; this library and the headless runner know nothing of
// them, and a build without the app does not list them (CLI11 refuses them as unknown).
#pragma once
#include "clothtear/types.h"

#include <functional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace clothtear {

// One --cut: a knife stroke (knife.h) applied between frames once the run reaches `time`.
struct CutRequest {
    double time = 0;            // s, simulated (the T: prefix; 0: before the first frame)
    std::vector<Vec2d> stroke;  // m: points (u, v) in the mesh's knifeFrame (u right, v up, from the
                                // middle of its extent; the built-in meshes: x and y)
    std::string text;           // as given, for messages
};

// Parses "[T:]U,V;U,V;...": every number a plain decimal (a point per ';', two numbers per point),
// then checkStroke (knife.h). The error names what was wrong, without the option's name.
Result<CutRequest> parseCut(const std::string& text);

struct RunOptions {
    bool headless = false;         // --headless: no window; run, then print or write the report
    std::string scene = "curtain"; // --scene: a name of --list-scenes, obj:PATH or SCENE:obj:PATH (--mesh)
    double seconds = 5.0;          // --seconds: simulated seconds of a headless run
    std::vector<std::string> sets; // key=value, in order: the --config file's first, then --set
    std::string config;            // --config FILE ("" for none); already folded into scene and sets
    std::string json;              // report path, "-" for stdout, "" for none
    std::string exportObj;         // --export-obj FILE: the cloth as it ends, torn, as OBJ with UVs
    std::string load;              // --load FILE: start from a world file (world_file.h), not the scene
    std::string save;              // --save FILE: the world as it ends, as a world file
    std::vector<CutRequest> cuts;  // --cut, repeatable, in order of time (equal times as given)
    std::string audioOut;          // --audio-out FILE: the run's soundtrack as a WAV (src/audio; the app's too)
    bool listScenes = false;
    bool listParams = false;
    bool version = false;
};

// What a front end adds to the shared options.
struct RunOptionsExtension {
    // Registers the front end's options on the parser, after the shared ones (--help lists them so).
    std::function<void(CLI::App&)> add;
    // Runs after --version and the lists were answered and before the config file is read. Returns
    // "" to go on, or why this combination is refused (one line, printed as "clothtear: <why>", exit 2).
    std::function<std::string(const CLI::App&, const RunOptions&)> check;
};

// Parses argv with a configured CLI11 parser, the same way for every clothtear program: -1 to go on,
// 0 after --help (printed on stdout), 2 on bad input ("<program>: <what> (see --help)" on stderr).
int parseCommandLine(CLI::App& app, int argc, char** argv, const char* program);

// Parses argv into `options` (and the extension's own variables). Returns -1 to go on, or an exit
// status: 0 after --help, --version, --list-scenes or --list-params (answered on stdout), 2 on bad
// input (one line on stderr).
int parseRunOptions(int argc, char** argv, RunOptions& options, const RunOptionsExtension& extension = {});

} // namespace clothtear
