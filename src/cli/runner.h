// The headless runner: run a scene with no window and write the JSON report. `clothtear --headless`
// (with or without the app) and the app's exit report use it; it knows nothing of window options.
#pragma once
#include "run_options.h"

#include "clothtear/world.h"

#include <nlohmann/json.hpp>
#include <span>
#include <string>

namespace clothtear {

// Runs options.scene for options.seconds with no window and writes the report. Exit status.
int runHeadless(const RunOptions& options);

// Applies the cuts of `cuts` from `next` on whose time has come (the world's time plus half a frame:
// between frames, never inside one), advancing `next`. Both front ends call it before each frame.
void applyDueCuts(World& world, const std::vector<CutRequest>& cuts, size_t& next);

// The report of a finished run (see README for the fields).
nlohmann::json makeReport(const World& world, const std::string& scene, double wallSeconds);

// --load: the world of a world file (world_file.h) with `overrides` ("key=value", checked by
// parseRunOptions) applied on top. Returns "" or the one-line message; on error `world` is unchanged.
std::string loadWorldFile(World& world, const std::string& path, std::span<const std::string> overrides = {});

// The report's "loaded" field: the file and where the world stood when it was loaded.
nlohmann::json loadedReport(const std::string& path, const World& atLoad);

} // namespace clothtear
