// Every tunable parameter of the simulation: its default (here), unit and meaning.
// The defaults below are the only ones: the parameter table (src/core/params.cpp, params.h) reads them
// from a default Settings. Ranges are not repeated here: the table holds each field's safe and valid
// range, and --set, config files, the UI panel and validation all check against it. To read them:
// `clothtear --list-params` or docs/parameters.md (generated from the table).
#pragma once
#include <cstdint>

namespace clothtear {

// The first three are explicit (springs as forces, src/core/step/integrate.cpp); the last two are
// the references a user would pick instead: implicit Euler (src/core/step/implicit_euler.h) and XPBD
// (src/core/step/xpbd.h), both stable at any sub-step and never touched by the stability guard.
enum class Integrator : int32_t { SemiImplicitEuler = 0, ForwardEuler = 1, Verlet = 2, ImplicitEuler = 3, Xpbd = 4 };
inline bool isExplicit(Integrator i) { return i == Integrator::SemiImplicitEuler || i == Integrator::ForwardEuler || i == Integrator::Verlet; }
enum class AirModel : int32_t { Drag = 0, Keserica = 1 };
// How semi-implicit Euler takes the springs' damping (time.damping; integrate.cpp): explicitly, or
// implicitly (one Jacobi step after the other forces: stable at any step, a second spring pass),
// or auto: implicitly where the explicit damping would make the stability guard soften the
// material (its step past time.max_substeps) and the implicit one would not, or where the implicit
// damping's sub-steps cost less (kImplicitDampingCost, world.h).
enum class DampingMode : int32_t { Explicit = 0, Implicit = 1, Auto = 2 };
// How the length limit's passes apply their corrections (src/core/step/limit.cpp):
//   GaussSeidel  in place, spring after spring, in one canonical order (the scan's)
//   Jacobi       averaged and over-relaxed, each spring's share divided by its ends' correction counts
enum class LimitSolver : int32_t { GaussSeidel = 0, Jacobi = 1 };
// The material law of the springs (include/clothtear/kes.h, docs/kes-material.md):
//   Linear  Hooke structural and bend-shear springs (material.stretch_* / bend_*)
//   Kes     Tagawa et al. 2003: the KES-FB1 tensile polynomial on the structural springs and the
//           hysteretic bending rate model (KES-FB2) on a hinge per interior edge, instead of the
//           bend-shear springs
enum class MaterialModel : int32_t { Linear = 0, Kes = 1 };
enum class MeshType : int32_t { Grid = 0, Irregular = 1, Obj = 2 };
enum class PinMode : int32_t { None = 0, TopEdge = 1, TopCorners = 2, LeftRightEdges = 3, LeftEdge = 4 };

struct TimeSettings {
    float frameDt = 1.0f / 60.0f; // s       simulated time per frame
    int32_t substeps = 10;        // count   sub-steps per frame (sub-step dt = frameDt / substeps)
    Integrator integrator = Integrator::SemiImplicitEuler;
    float verletFriction = 0.01f; // fraction of velocity lost per Verlet step (Keserica 2.2.1 "f")
    bool stabilityGuard = true;   // raise sub-steps up to maxSubsteps for the stable step, then cap each spring
    int32_t maxSubsteps = 200;    // count   most sub-steps per frame the guard may use: the material
                                  // keeps the stiffness the user set (a finer or smaller cloth takes more
                                  // sub-steps) up to this budget, past it springs are capped; at or below
                                  // time.substeps it only caps (bench/README.md "Does the cloth hold?")
    // Semi-implicit Euler with the linear material (DampingMode). Explicit damping bounds the step
    // by m / sum(kd), which shrinks as the spacing squared: a fine or small cloth took several
    // times the sub-steps its stiffness needs, and past time.max_substeps the guard softened it
    // (bench/README.md, "The springs' damping and the guard's step").
    DampingMode damping = DampingMode::Auto;
    float cgTolerance = 1e-5f;    // relative residual  implicit Euler: conjugate-gradient stop
    int32_t cgMaxIterations = 200; // count   implicit Euler: conjugate-gradient iteration cap
};

struct MaterialSettings {
    float density = 0.2f;          // kg/m^2  areal density, lumped to particles from rest areas
    float stretchStiffness = 60.f; // N/m     membrane stiffness; per spring k = value * area/len^2
    float stretchDamping = 0.01f;  // N s/m   damping along the spring, same scaling
    float bendStiffness = 4.f;     // N/m     bend-shear springs (Onal 3.1.2)
    float bendDamping = 0.001f;    // N s/m   bend-shear spring damping
    MaterialModel model = MaterialModel::Linear;
    // kes: tension per unit width T(e) = t1 e + t2 e^2 + t3 e^3 + t4 e^4 in gf/cm with e the strain in
    // percent, as KES-FB1 prints it (Tagawa Fig. 8(a): t2 = 8.5748, t4 = 0.1191). Converted to SI in
    // one place, kesLawSI (src/core/kes.cpp).
    float kesT1 = 0.f;          // gf/cm per %
    float kesT2 = 8.5748f;      // gf/cm per %^2
    float kesT3 = 0.f;          // gf/cm per %^3
    float kesT4 = 0.1191f;      // gf/cm per %^4
    // kes: bending moment per unit width, rate model M = D K +/- D1 (1 - exp(-alpha |K - K_r|)) from
    // the last reversal K_r (Tagawa Eq. 3-4, Fig. 8(b)).
    float kesBendD = 0.12266f;  // gf cm^2/cm  bending rigidity B
    float kesBendD1 = 0.1181f;  // gf cm/cm    hysteresis, the loop's width at K = 0 (2HB)
    float kesBendAlpha = 24.94f; // cm         how fast the hysteresis saturates after a reversal
    // kes: how far (1/m, SI: a numerical choice of this project, not a KES coefficient) the curvature
    // must come back from its extreme before the rate model starts a new branch there; smaller
    // reversals (a sub-step's jitter) retrace the tentative branch and leave the memory as it was
    // (docs/kes-material.md, "Reversals and jitter").
    float kesBendReversal = 0.3f; // 1/m
};

struct AirSettings {
    AirModel model = AirModel::Drag;
    float dragCoefficient = 0.5f;   // kg/(m^2 s)  F = -c * area * v_rel (physical default)
    float kesericaFactor = 0.1f;    // fraction of velocity removed per sub-step (Keserica 2.3)
};

struct GravitySettings {
    float x = 0.f, y = -9.81f, z = 0.f; // m/s^2 (up is +y)
};

struct LimitSettings {
    bool enabled = true;       // Provot length limiting (Provot 1995; Onal 2.1.1)
    float maxStretch = 0.10f;  // ratio   springs longer than rest*(1+maxStretch) are pulled back
    int32_t iterations = 12;   // count   Jacobi passes per sub-step
    float relaxation = 1.5f;   // factor  over-relaxation of the averaged Jacobi correction
    LimitSolver solver = LimitSolver::GaussSeidel;
};

struct WindSettings {
    bool enabled = false;
    float dirX = 0.f, dirY = 0.f, dirZ = 1.f; // direction (normalized at use)
    float speed = 6.f;          // m/s     mean air speed
    float gust = 0.5f;          // ratio   gust amplitude relative to speed
    float gustFrequency = 0.7f; // Hz      gust frequency
    float dragCoefficient = 1.f; // kg/m^3  F = c * area * (n.v_rel) |n.v_rel| on a triangle
};

struct CollisionSettings {
    bool ground = true;        // infinite plane y = groundHeight
    float groundHeight = -3.f; // m       height of the ground plane
    float friction = 0.3f;     // Coulomb coefficient between cloth and colliders
    float thickness = 0.005f;  // m       cloth half-thickness kept between cloth and colliders
    float stretchBand = 0.05f; // m       fabric within this rest distance of a ball's contact may stretch
                               //         to the tear threshold, like the contact itself (limit.cpp)
    float ballDensity = 200.f; // kg/m^3, informational default for the ball tool
    bool broadPhase = true;    //         ball phases test only the triangles of particles near each ball
};

struct TearSettings {
    bool enabled = true;
    float threshold = 0.35f;        // strain  basic tear when (len-rest)/rest exceeds it
    float weakThreshold = 0.2f;     // strain  lower threshold for springs touching a weak point
    float onePointThreshold = 0.2f; // strain  threshold for one-point connections
    float seamStrength = 3.f;       // x threshold  springs touching a hem (pinned edge) tear at this multiple
    float gaugeLength = 0.125f;     // m       where no hand pulls, a shorter spring's strain is the mean strain
                                    //         of a line of springs this long through it (limit.cpp)
    float tipRadius = 0.5f;         // m       a weak-point tear runs across the fabric's tension within this
                                    //         distance of its tip (tear_tension.h); 0: across the tense spring
    int32_t maxPerStep = 64;        // count   cap on tears per sub-step
    bool validate = false;          // run the full topology validation after every tear
};

struct ClothSettings {
    MeshType mesh = MeshType::Grid;
    int32_t resolutionX = 40;  // particles across
    int32_t resolutionY = 40;  // particles down
    float width = 2.f;         // m
    float height = 2.f;        // m
    float jitter = 0.3f;       // fraction of spacing  irregular mesh only
    int32_t seed = 1;          // irregular mesh seed
    PinMode pin = PinMode::TopEdge;
    float tilt = 0.f;          // deg  rotation about the top edge (0 = hanging vertical, 90 = horizontal)
};

// A cloth at rest stops being simulated until something can touch it (src/core/sleep.cpp).
struct SleepSettings {
    bool enabled = true;  // sleep when every particle is slower than `speed` for `delay` seconds
    float speed = 1e-2f;  // m/s  at rest: every particle moved slower than this over a frame
                          // (the length limit keeps particles of a curtain at rest jittering at up
                          // to 6 mm/s at 64x64: 0.1 mm per frame, invisible, but never below 1e-3)
    float delay = 1.f;    // s    at rest this long before sleeping
};

struct SceneParams {
    float pullAngle = 0.f;   // deg  pull scene: direction in the cloth plane, 0 = straight down
    float pullSpeed = 0.5f;  // m/s  pull scene: speed of the grabbed particle
    float tensionSpeed = 0.5f; // m/s tension scene: each clamp moves outward at this speed
    bool tensionNotch = false; // tension scene: pre-cut slit in the middle
    float ballRadius = 0.5f; // m    thrown balls
    float ballSpeed = 8.f;   // m/s  thrown balls (the tool from the start camera needs about 5)
    float ballMass = 2.f;    // kg   thrown balls
    float ballHeight = 0.5f; // fraction of cloth height from bottom where the ball is aimed
    // m: the hand's size. A drag (app) and the pull scene hold every particle within this distance
    // in the material (rest space) of the grabbed one, so a pull acts on the same patch of cloth at
    // any resolution; 0 holds the one particle.
    float grabRadius = 0.08f;
    // rad/s: impulse-rotation scene, the angular velocity the impulse gives the hanging strip about
    // its clamp (Tagawa 2003 Fig. 11; the impulse's size is not in the text: 24 rad/s is what a rigid
    // strip of 0.1 m needs to just reach the measured 2.88 rad, docs/kes-material.md).
    float impulseSpin = 24.f;
    // m: swing-vacuum scene, how far out (along the cloth's normal) the free end starts, the strip
    // bent into an arc below its clamp (Tagawa 2003 Fig. 9: the end swings within +-60 mm).
    float swingOffset = 0.06f;
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
