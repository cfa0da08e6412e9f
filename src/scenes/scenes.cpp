// Scene definitions. Each scene: name, one-line description, defaults, and what it adds to the world.
#include "clothtear/scenes.h"

#include "clothtear/params.h"

#include <cmath>

namespace clothtear {
namespace {

void noPopulate(World&) {}

// ---- cloth core scenes --------------------------------------------------------------------------

void curtainConfig(Settings&) {}

void cornersConfig(Settings& s) { s.cloth.pin = PinMode::TopCorners; }

void flagConfig(Settings& s) {
    s.cloth.pin = PinMode::LeftEdge;
    s.cloth.width = 3.f;
    s.cloth.height = 2.f;
    s.cloth.resolutionX = 45;
    s.cloth.resolutionY = 30;
    s.wind.enabled = true;
    s.wind.dirX = 1.f;
    s.wind.dirY = 0.f;
    s.wind.dirZ = 0.15f;
    s.wind.speed = 8.f;
    s.tear.enabled = false;
}

void dropConfig(Settings& s) {
    s.cloth.pin = PinMode::None;
    s.cloth.tilt = 90.f; // horizontal
    s.tear.enabled = false;
    s.collision.groundHeight = -3.f;
}
void dropPopulate(World& w) {
    // A heavy ball resting on the ground under the middle of the cloth.
    Ball b;
    b.radius = 0.6f;
    b.mass = 50.f;
    // The tilt swings the cloth about its top edge towards +z, so its middle is at z = height / 2.
    b.x = Vec3(0.f, w.settings.collision.groundHeight + b.radius, 0.5f * w.settings.cloth.height);
    w.balls.push_back(b);
}

void irregularConfig(Settings& s) { s.cloth.mesh = MeshType::Irregular; }

const SceneDef kScenes[] = {
    {"curtain", "Cloth hanging from its top edge", curtainConfig, noPopulate},
    {"corners", "Cloth hanging from its two top corners", cornersConfig, noPopulate},
    {"flag", "Flag pinned along its left edge, gusty wind", flagConfig, noPopulate},
    {"drop", "Free horizontal cloth falls onto a ball resting on the ground", dropConfig, dropPopulate},
    {"irregular", "Curtain on a non-uniform (jittered) triangle mesh", irregularConfig, noPopulate},
};

} // namespace

std::span<const SceneDef> allScenes() { return kScenes; }

const SceneDef* findScene(std::string_view name) {
    for (const SceneDef& s : kScenes)
        if (name == s.name) return &s;
    return nullptr;
}

std::string loadScene(World& world, std::string_view name, std::span<const std::string> overrides) {
    Settings settings;
    const SceneDef* scene = nullptr;
    MeshData objMesh;
    const bool isObj = name.starts_with("obj:");
    if (isObj) {
        Result<MeshData> loaded = loadObj(std::string(name.substr(4)));
        if (!loaded.ok()) return loaded.error;
        objMesh = std::move(loaded.value);
        settings.cloth.mesh = MeshType::Obj;
    } else {
        scene = findScene(name);
        if (!scene) {
            std::string names;
            for (const SceneDef& s : kScenes) names += std::string(names.empty() ? "" : ", ") + s.name;
            return "unknown scene '" + std::string(name) + "' (scenes: " + names + ", obj:PATH)";
        }
        scene->configure(settings);
    }
    for (const std::string& o : overrides)
        if (std::string err = applyAssignment(settings, o); !err.empty()) return err;
    World next;
    next.settings = settings;
    if (isObj && settings.cloth.mesh != MeshType::Obj) next.settings.cloth.mesh = MeshType::Obj;
    std::string err = isObj ? next.rebuild(objMesh) : next.rebuild();
    if (!err.empty()) return err;
    if (scene) scene->populate(next);
    world = std::move(next);
    return {};
}

} // namespace clothtear
