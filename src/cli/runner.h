// The headless runner: command-line options, running a scene with no window, and the JSON report.
// Shared by the `clothtear` executable with or without the app.
#pragma once
#include "clothtear/world.h"

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace clothtear {

struct CliOptions {
    bool headless = false;
    std::string scene = "curtain";
    double seconds = 5.0;
    std::vector<std::string> sets; // key=value, in order: the --config file's first, then --set
    std::string config;            // --config FILE ("" for none); already folded into scene and sets
    std::string json;              // report path, "-" for stdout, "" for none
    bool listScenes = false;
    bool listParams = false;
    bool version = false;
    // App-only options (ignored by the headless runner).
    int frames = -1;
    std::string screenshot;
    std::string script;
    std::string record;
};

// Parses argv. Returns -1 to continue, or an exit status (0 after --help/--version, 2 on bad input,
// with the message already printed to stderr).
int parseCommandLine(int argc, char** argv, CliOptions& options, bool appAvailable);

// Runs options.scene for options.seconds with no window and writes the report. Exit status.
int runHeadless(const CliOptions& options);

// The report of a finished run (see README for the fields).
nlohmann::json makeReport(const World& world, const std::string& scene, double wallSeconds);

} // namespace clothtear
