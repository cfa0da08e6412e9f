// The scene library, shared by the app's scene picker, the headless runner, the tests and the
// benchmarks. A scene sets parameter defaults, then (after user overrides) populates the world.
#pragma once
#include "clothtear/world.h"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace clothtear {

struct SceneDef {
    const char* name;
    const char* description;
    void (*configure)(Settings&); // scene defaults, applied before user overrides
    void (*populate)(World&);     // after the cloth is built: balls, drivers, extra pins, cuts
};

std::span<const SceneDef> allScenes();
const SceneDef* findScene(std::string_view name);

// Loads scene `name` ("obj:PATH" for an OBJ file) into `world`: defaults, then each "key=value" of
// `overrides` in order, then the build. Returns "" or one message saying what was wrong; on error
// the world is left as it was.
std::string loadScene(World& world, std::string_view name, std::span<const std::string> overrides = {});

} // namespace clothtear
