// Every tunable parameter of the simulation, with its default, unit and valid range.
// The parameter table (params.h) names each field once; --set, the UI panel, validation and the
// docs all read from that table, so the defaults below are the single source of truth.
#pragma once
#include <cstdint>

namespace clothtear {

// The first three are explicit (springs as forces, src/core/step/integrate.cpp); the last two are
// the references a user would pick instead: implicit Euler (src/core/implicit_euler.h) and XPBD
// (src/core/xpbd.h), both stable at any sub-step and never touched by the stability guard.
enum class Integrator : int32_t { SemiImplicitEuler = 0, ForwardEuler = 1, Verlet = 2, ImplicitEuler = 3, Xpbd = 4 };
inline bool isExplicit(Integrator i) { return i == Integrator::SemiImplicitEuler || i == Integrator::ForwardEuler || i == Integrator::Verlet; }
enum class AirModel : int32_t { Drag = 0, Keserica = 1 };
enum class MeshType : int32_t { Grid = 0, Irregular = 1, Obj = 2 };
enum class PinMode : int32_t { None = 0, TopEdge = 1, TopCorners = 2, LeftRightEdges = 3, LeftEdge = 4 };

struct TimeSettings {
    float frameDt = 1.0f / 60.0f; // s, [1e-4, 0.1]   simulated time per frame
    int32_t substeps = 10;        // count, [1, 500]  sub-steps per frame (sub-step dt = frameDt / substeps)
    Integrator integrator = Integrator::SemiImplicitEuler;
    float verletFriction = 0.01f; // fraction of velocity lost per Verlet step (Keserica 2.2.1 "f"), [0, 1]
    bool stabilityGuard = true;   // raise sub-steps up to maxSubsteps for the stable step, then cap each spring
    int32_t maxSubsteps = 10;     // count, [1, 2000]  most sub-steps per frame the guard may use (default:
                                  // time.substeps, so it only caps springs and keeps the frame budget; see
                                  // bench/README.md "Stability" for what raising it costs and buys)
    float cgTolerance = 1e-5f;    // relative residual, [1e-10, 0.1]  implicit Euler: conjugate-gradient stop
    int32_t cgMaxIterations = 200; // count, [1, 100000]  implicit Euler: conjugate-gradient iteration cap
};

struct MaterialSettings {
    float density = 0.2f;          // kg/m^2, (0, 10]  areal density, lumped to particles from rest areas
    float stretchStiffness = 60.f; // N/m, [0, 1e5]    membrane stiffness; per spring k = value * area/len^2
    float stretchDamping = 0.01f;  // N s/m, [0, 1e3]  damping along the spring, same scaling
    float bendStiffness = 4.f;     // N/m, [0, 1e5]    bend-shear springs (Onal 3.1.2)
    float bendDamping = 0.001f;    // N s/m, [0, 1e3]
};

struct AirSettings {
    AirModel model = AirModel::Drag;
    float dragCoefficient = 0.5f;   // kg/(m^2 s), [0, 100]  F = -c * area * v_rel (physical default)
    float kesericaFactor = 0.1f;    // fraction of velocity removed per sub-step (Keserica 2.3), [0, 1]
};

struct GravitySettings {
    float x = 0.f, y = -9.81f, z = 0.f; // m/s^2, [-100, 100] each
};

struct LimitSettings {
    bool enabled = true;       // Provot length limiting (Provot 1995; Onal 2.1.1)
    float maxStretch = 0.10f;  // ratio, [0.001, 1]  springs longer than rest*(1+maxStretch) are pulled back
    int32_t iterations = 12;   // count, [0, 200]   Jacobi passes per sub-step
    float relaxation = 1.5f;   // factor, [0.1, 2]  over-relaxation of the averaged Jacobi correction
};

struct WindSettings {
    bool enabled = false;
    float dirX = 0.f, dirY = 0.f, dirZ = 1.f; // direction (normalized at use), [-1, 1] each
    float speed = 6.f;          // m/s, [0, 100]    mean air speed
    float gust = 0.5f;          // ratio, [0, 2]    gust amplitude relative to speed
    float gustFrequency = 0.7f; // Hz, [0, 20]
    float dragCoefficient = 1.f; // kg/m^3-like scale, [0, 100] F = c * area * (n.v_rel) |n.v_rel| on a triangle
};

struct CollisionSettings {
    bool ground = true;        // infinite plane y = groundHeight
    float groundHeight = -3.f; // m, [-100, 100]
    float friction = 0.3f;     // Coulomb coefficient, [0, 2]
    float thickness = 0.005f;  // m, [0, 0.1]  cloth half-thickness kept between cloth and colliders
    float ballDensity = 200.f; // kg/m^3, informational default for the ball tool
    bool broadPhase = true;    // ball phases test only the triangles of particles near each ball
};

struct TearSettings {
    bool enabled = true;
    float threshold = 0.35f;        // strain, [0.01, 10]  basic tear when (len-rest)/rest exceeds it
    float weakThreshold = 0.2f;     // strain, [0.005, 10] lower threshold for springs touching a weak point
    float onePointThreshold = 0.2f; // strain, [0.005, 10] threshold for one-point connections
    int32_t maxPerStep = 64;        // count, [1, 100000]  cap on tears per sub-step
    bool validate = false;          // run the full topology validation after every tear
};

struct ClothSettings {
    MeshType mesh = MeshType::Grid;
    int32_t resolutionX = 40;  // particles, [2, 1024]
    int32_t resolutionY = 40;  // particles, [2, 1024]
    float width = 2.f;         // m, [0.05, 100]
    float height = 2.f;        // m, [0.05, 100]
    float jitter = 0.3f;       // fraction of spacing, [0, 0.45]  irregular mesh only
    int32_t seed = 1;          // irregular mesh seed
    PinMode pin = PinMode::TopEdge;
    float tilt = 0.f;          // deg, [-90, 90] rotation about the top edge (0 = hanging vertical, 90 = horizontal)
};

// A cloth at rest stops being simulated until something can touch it (src/core/sleep.cpp).
struct SleepSettings {
    bool enabled = true;  // sleep when every particle is slower than `speed` for `delay` seconds
    float speed = 1e-2f;  // m/s, [1e-6, 1]  at rest: every particle moved slower than this over a frame
                          // (the length limit keeps particles of a curtain at rest jittering at up
                          // to 6 mm/s at 64x64: 0.1 mm per frame, invisible, but never below 1e-3)
    float delay = 1.f;    // s, [0, 60]      at rest this long before sleeping
};

struct SceneParams {
    float pullAngle = 0.f;   // deg, [-180, 180] pull scene: direction in the cloth plane, 0 = straight down
    float pullSpeed = 0.5f;  // m/s, [0, 20]
    float tensionSpeed = 0.5f; // m/s, [0, 20] tension scene: each clamp moves outward at this speed
    bool tensionNotch = false; // tension scene: pre-cut slit in the middle
    float ballRadius = 0.5f; // m, [0.01, 10]
    float ballSpeed = 3.f;   // m/s, [0, 100]
    float ballMass = 2.f;    // kg, [0.01, 1000]
    float ballHeight = 0.5f; // fraction of cloth height from bottom where the ball is aimed, [0, 1]
};

struct CheckSettings {
    bool finite = false; // scan for NaN/Inf at every phase boundary and report the phase and particle
                         // (World::nonFiniteWhere); always on in Debug builds
};

struct Settings {
    TimeSettings time;
    MaterialSettings material;
    AirSettings air;
    GravitySettings gravity;
    LimitSettings limit;
    WindSettings wind;
    CollisionSettings collision;
    TearSettings tear;
    ClothSettings cloth;
    SleepSettings sleep;
    SceneParams scene;
    CheckSettings check;
};

} // namespace clothtear
