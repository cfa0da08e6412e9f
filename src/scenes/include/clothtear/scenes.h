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

// A scene name: a setup of allScenes() on the grid or irregular mesh of its settings, "obj:PATH" (the
// curtain setup on an OBJ mesh) or "SETUP:obj:PATH" (any setup on an OBJ mesh: pins, the pull's
// hand and the ball read the mesh's own frame, meshFrame in mesh.h).
struct SceneName {
    const SceneDef* setup = nullptr;
    std::string objPath; // empty: the mesh of cloth.mesh
};
Result<SceneName> parseSceneName(std::string_view name);
// The name parseSceneName reads back as `setup` on `objPath` (just `setup` when the path is empty).
std::string composeSceneName(std::string_view setup, std::string_view objPath);

// Loads scene `name` (see SceneName) into `world`: defaults, then each "key=value" of
// `overrides` in order, then the build. Returns "" or one message saying what was wrong; on error
// the world is left as it was.
std::string loadScene(World& world, std::string_view name, std::span<const std::string> overrides = {});

// What the vacuum scenes (swing-vacuum, impulse-rotation; Tagawa 2003 Fig. 10, 12) measure: the
// strip's free end against its clamp. The particles nearest the middle of the top and bottom edges
// of the rest mesh, the direction the strip hangs (-up of the rest frame) and the direction it swings
// out to (the rest frame's normal: cloth.tilt and impulse.spin move it that way).
struct StripProbe {
    Index top = 0, tip = 0;
    Vec3d down = -Vec3d::UnitY(), out = Vec3d::UnitZ();
};
StripProbe stripProbe(const World& world);
// m: the free end's offset from the clamp along `out` (the swing's amplitude, Fig. 10).
double stripOffset(const World& world, const StripProbe& probe);
// rad: the angle of clamp -> free end from hanging straight down, positive towards `out` (Fig. 12).
double stripAngle(const World& world, const StripProbe& probe);

// What a user should know about a loaded scene that is not an error (every particle pinned), or "".
std::string sceneWarnings(const World& world);

} // namespace clothtear
