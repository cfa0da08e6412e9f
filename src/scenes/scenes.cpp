// Scene definitions. Each scene: name, one-line description, defaults, and what it adds to the world.
#include "clothtear/scenes.h"

#include "clothtear/params.h"
#include "clothtear/tear.h"

#include <algorithm>

#include <cmath>

namespace clothtear {
namespace {

void noPopulate(World&) {}

std::vector<Vec3d> positionsOf(const Cloth& c) {
    std::vector<Vec3d> x(c.x.size());
    for (size_t p = 0; p < x.size(); ++p) x[p] = c.x[p].cast<double>();
    return x;
}

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
    // Under the middle of the cloth as it starts (the tilt has swung it flat towards +z).
    const Vec3d mid = meshFrame(positionsOf(w.cloth)).centre;
    b.x = Vec3(float(mid.x()), w.settings.collision.groundHeight + b.radius, float(mid.z()));
    w.balls.push_back(b);
}

// Swing: pinned at its two top corners, released from horizontal; smooth motion (no tearing, no
// ground) for the accuracy measurements of clothbench (bench/README.md).
void swingConfig(Settings& s) {
    s.cloth.pin = PinMode::TopCorners;
    s.cloth.tilt = 90.f;
    s.tear.enabled = false;
    s.collision.ground = false;
}

void irregularConfig(Settings& s) { s.cloth.mesh = MeshType::Irregular; }

// ---- tearing scenes (Onal chapter 4) ----------------------------------------------------------------

// The default cloth for the tearing experiments, documented in README ("Tearing scenes").
void tearClothConfig(Settings& s) {
    s.cloth.width = 6.f;
    s.cloth.height = 6.f;
    s.cloth.resolutionX = 48;
    s.cloth.resolutionY = 48;
    s.collision.groundHeight = -5.f;
    // The default threshold. A sweep over ball mass {5, 10, 20} kg at 0.9x, 1x and 1.1x of it: all
    // five ball outcomes hold for 5 and 10 kg (README, "Tearing scenes").
    s.tear.threshold = 0.35f;
    s.tear.weakThreshold = 0.15f;
    s.tear.onePointThreshold = 0.15f;
    s.scene.ballMass = 10.f;
}

// Pull: top edge pinned, a hand dragged at pull.speed along pull.angle in the cloth plane (0 =
// straight down, positive towards +x). The hand holds every particle within grab.radius (rest space)
// of the bottom centre: a 0.3 m hand on the 6 m sheet. Holding one particle instead made the
// outcome a matter of resolution: the particle's few springs tore and it came out alone (3 tears at
// 40 and 80 a side, issue 13); the hand's rim is a fixed length of cloth at every resolution.
void pullConfig(Settings& s) {
    tearClothConfig(s);
    s.collision.ground = false;
    s.scene.grabRadius = 0.3f; // a hand on a 6 m sheet: the same patch at every resolution (issue 13)
}
void pullPopulate(World& w) {
    // The bottom centre of the mesh in its own plane, and the pull in that plane.
    const MeshFrame f = meshFrame(w.cloth.rest);
    const Vec3d bottom = f.at(0.5 * (f.minU + f.maxU), f.minV);
    Index grab = 0;
    double best = 1e300;
    for (Index p = 0; p < w.cloth.particleCount(); ++p) {
        const double d = (w.cloth.rest[p] - bottom).squaredNorm();
        if (d < best) best = d, grab = p;
    }
    const double a = w.settings.scene.pullAngle * (M_PI / 180.0);
    const double R = w.settings.scene.grabRadius;
    const Vec3d along = std::sin(a) * f.right - std::cos(a) * f.up;
    Driver d{{}, (along * w.settings.scene.pullSpeed).cast<float>()};
    for (Index p = 0; p < w.cloth.particleCount(); ++p)
        if (p == grab || (w.cloth.rest[p] - w.cloth.rest[grab]).norm() <= R) {
            w.cloth.setPinned(p, true);
            d.particles.push_back(p);
        }
    w.drivers.push_back(d);
}

// Tension: a sheet clamped along its left and right edges, the clamps moving apart; with tension.notch
// a short vertical slit in the middle starts the tear.
void tensionConfig(Settings& s) {
    tearClothConfig(s);
    s.cloth.pin = PinMode::LeftRightEdges;
    s.gravity.y = 0.f;
    s.collision.ground = false;
}
void tensionPopulate(World& w) {
    const MeshFrame f = meshFrame(w.cloth.rest);
    const double midU = 0.5 * (f.minU + f.maxU), midV = 0.5 * (f.minV + f.maxV);
    Driver left, right;
    for (Index p = 0; p < w.cloth.particleCount(); ++p) {
        if (!w.cloth.pinned(p)) continue;
        (f.u(w.cloth.rest[p]) < midU ? left : right).particles.push_back(p);
    }
    left.velocity = (-f.right * w.settings.scene.tensionSpeed).cast<float>();
    right.velocity = (f.right * w.settings.scene.tensionSpeed).cast<float>();
    w.drivers = {left, right};
    if (!w.settings.scene.tensionNotch) return;
    // Cut the spring along the pull (no "up" component) closest to the centre: a basic tear opens a
    // slit across the pull.
    Index best = kNone;
    double bestD = 1e300;
    const Vec3d mid = f.at(midU, midV);
    for (Index s = 0; s < w.cloth.springs.size(); ++s) {
        const Spring& sp = w.cloth.springs[s];
        const Vec3d d = w.cloth.rest[sp.b] - w.cloth.rest[sp.a];
        if (std::abs(d.dot(f.up)) > 1e-9 * d.norm()) continue;
        // Springs equally near (a grid's middle) go to the first: round-off must not pick.
        const double dist = (0.5 * (w.cloth.rest[sp.a] + w.cloth.rest[sp.b]) - mid).squaredNorm();
        if (dist < bestD - 1e-9 * d.squaredNorm()) bestD = dist, best = s;
    }
    TearContext ctx{w.settings.tear, 0.0, nullptr};
    if (best != kNone) forceTear(w.cloth, best, ctx);
}

// Ball experiments (Onal 4.1): cloth hanging from its top edge, a ball thrown horizontally (-z) at it.
void ballConfig(Settings& s, float radius, float speed, float height) {
    tearClothConfig(s);
    s.scene.ballRadius = radius;
    s.scene.ballSpeed = speed;
    s.scene.ballHeight = height;
}
void ballPopulate(World& w) {
    // Thrown at the cloth as it starts, along its normal, ball.height of the way up its middle.
    const SceneParams& sp = w.settings.scene;
    const MeshFrame f = meshFrame(positionsOf(w.cloth));
    const Vec3d aim = f.at(0.5 * (f.minU + f.maxU), f.minV + sp.ballHeight * f.height());
    Ball b;
    b.radius = sp.ballRadius;
    b.mass = sp.ballMass;
    b.x = (aim + (b.radius + 0.05) * f.normal).cast<float>();
    b.v = (-sp.ballSpeed * f.normal).cast<float>();
    w.balls.push_back(b);
}

const SceneDef kScenes[] = {
    {"pull", "Top edge pinned, a hand (grab.radius) at the bottom centre pulled along pull.angle: tear runs across the tension", pullConfig,
     pullPopulate},
    {"tension", "Sheet clamped at left and right, clamps moving apart (tension.notch=1: pre-cut slit)",
     tensionConfig, tensionPopulate},
    {"ball-r0.5-v3", "Ball r=0.5 m at 3 m/s into the hanging cloth (tears)",
     [](Settings& s) { ballConfig(s, 0.5f, 3.f, 0.5f); }, ballPopulate},
    {"ball-r1-v3-low", "Ball r=1 m at 3 m/s aimed low (slides under, no tear)",
     [](Settings& s) { ballConfig(s, 1.f, 3.f, 0.12f); }, ballPopulate},
    {"ball-r1-v3-high", "Ball r=1 m at 3 m/s aimed high (tears)", [](Settings& s) { ballConfig(s, 1.f, 3.f, 0.8f); },
     ballPopulate},
    {"ball-r2-v3", "Ball r=2 m at 3 m/s (cloth slides over it, no tear)",
     [](Settings& s) { ballConfig(s, 2.f, 3.f, 0.5f); }, ballPopulate},
    {"ball-r2-v10", "Ball r=2 m at 10 m/s (tears)", [](Settings& s) { ballConfig(s, 2.f, 10.f, 0.5f); },
     ballPopulate},

    {"curtain", "Cloth hanging from its top edge", curtainConfig, noPopulate},
    {"corners", "Cloth hanging from its two top corners", cornersConfig, noPopulate},
    {"swing", "Cloth pinned at its two top corners, released from horizontal (no tearing, no ground)", swingConfig,
     noPopulate},
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

Result<SceneName> parseSceneName(std::string_view name) {
    SceneName parsed;
    std::string_view setup = name;
    bool onObj = true;
    if (name.starts_with("obj:")) {
        setup = "curtain";
        parsed.objPath = name.substr(4);
    } else if (const size_t at = name.find(":obj:"); at != std::string_view::npos) {
        setup = name.substr(0, at);
        parsed.objPath = name.substr(at + 5);
    } else {
        onObj = false;
    }
    if (onObj && parsed.objPath.empty()) return {{}, "scene '" + std::string(name) + "': no OBJ path after 'obj:'"};
    parsed.setup = findScene(setup);
    if (!parsed.setup) {
        std::string names;
        for (const SceneDef& s : kScenes) names += std::string(names.empty() ? "" : ", ") + s.name;
        return {{}, "unknown scene '" + std::string(setup) + "' (scenes: " + names + ", obj:PATH, SCENE:obj:PATH)"};
    }
    return {std::move(parsed), {}};
}

std::string composeSceneName(std::string_view setup, std::string_view objPath) {
    if (objPath.empty()) return std::string(setup);
    return std::string(setup) + ":obj:" + std::string(objPath);
}

std::string loadScene(World& world, std::string_view name, std::span<const std::string> overrides) {
    Result<SceneName> parsed = parseSceneName(name);
    if (!parsed.ok()) return parsed.error;
    const SceneName& scene = parsed.value;
    const bool isObj = !scene.objPath.empty();
    Settings settings;
    MeshData objMesh;
    if (isObj) {
        Result<MeshData> loaded = loadObj(scene.objPath);
        if (!loaded.ok()) return loaded.error;
        objMesh = std::move(loaded.value);
    }
    scene.setup->configure(settings);
    if (isObj) settings.cloth.mesh = MeshType::Obj;
    for (const std::string& o : overrides)
        if (std::string err = applyAssignment(settings, o); !err.empty()) return err;
    World next;
    next.settings = settings;
    if (isObj && settings.cloth.mesh != MeshType::Obj) next.settings.cloth.mesh = MeshType::Obj;
    std::string err = isObj ? next.rebuild(objMesh) : next.rebuild();
    // buildCloth calls its input "mesh"; from a file, name the file (non-manifold edges).
    if (isObj && err.starts_with("mesh: ")) err = scene.objPath + err.substr(4);
    if (!err.empty()) return err;
    scene.setup->populate(next);
    world = std::move(next);
    return {};
}

std::string sceneWarnings(const World& world) {
    const Cloth& c = world.cloth;
    Index pinned = 0;
    for (Index p = 0; p < c.particleCount(); ++p) pinned += c.pinned(p) ? 1 : 0;
    if (c.particleCount() > 0 && pinned == c.particleCount())
        return "every particle is pinned: the cloth cannot move (cloth.pin on this mesh's extent; try "
               "another cloth.pin)";
    return {};
}

} // namespace clothtear
