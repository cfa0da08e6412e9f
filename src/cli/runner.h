// The headless runner: run a scene with no window and write the JSON report. `clothtear --headless`
// (with or without the app) and the app's exit report use it; it knows nothing of window options.
#pragma once
#include "run_options.h"

#include "clothtear/world.h"

#include <nlohmann/json.hpp>
#include <string>

namespace clothtear {

// Runs options.scene for options.seconds with no window and writes the report. Exit status.
int runHeadless(const RunOptions& options);

// The report of a finished run (see README for the fields).
nlohmann::json makeReport(const World& world, const std::string& scene, double wallSeconds);

} // namespace clothtear
