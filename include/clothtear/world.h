// The world: one cloth, balls, kinematic drivers, settings, and the step.
//
// A frame is `time.substeps` sub-steps. Each sub-step runs named phases, each timed into StepProfile:
//   forces -> springs -> wind -> integrate -> collide -> limit -> contact -> tear -> bookkeeping
// A phase the scene does not need is not entered (no wind: no wind loop; no balls: no collide
// phase, and no contact phase without the ground either; tearing off: no strain scan). Topology
// changes (tearing) happen only in the tear phase, between the others.
#pragma once
#include "clothtear/cloth.h"
#include "clothtear/knife.h"
#include "clothtear/settings.h"
#include "clothtear/tear.h"
#include "clothtear/tear_events.h"
#include "clothtear/types.h"

#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace clothtear {

enum class Phase : int { Forces, Springs, Wind, Integrate, Collide, Limit, Contact, Tear, Bookkeeping, Count };
const char* phaseName(Phase p);

struct StepProfile {
    std::array<double, int(Phase::Count)> ms{};     // accumulated milliseconds per phase
    std::array<uint64_t, int(Phase::Count)> runs{}; // how often each phase was entered
    uint64_t substeps = 0;
    // Sub-steps that took the springs' damping implicitly (time.damping; World::guardSubsteps), and
    // whether the last frame did.
    uint64_t dampingImplicitSubsteps = 0;
    bool dampingImplicit = false;
    uint64_t solverIterations = 0; // implicit Euler: conjugate-gradient iterations, summed
    // Length limit not converged: sub-steps whose last allowed pass (limit.iterations) still
    // corrected springs, and those springs, summed. The cloth then ends the sub-step stretched past
    // the limit (e.g. a fine cloth in wind at few sub-steps: README "Status and known gaps").
    uint64_t limitCapped = 0;
    uint64_t limitCappedSprings = 0;
    uint64_t limitPasses = 0; // passes of the length limit run, summed over sub-steps
    // Of them, Gauss-Seidel passes split over the threads by region of the cloth (several threads,
    // a list of 128 springs or more; src/core/step/limit.cpp, regionPasses).
    uint64_t limitRegionPasses = 0;
    // Sub-steps whose limit skipped the tethers (no spring past their reach) and whose limit skipped
    // listing the springs the tethers' pull may have put over it (a scan found none): both exact.
    uint64_t limitTethersSkipped = 0;
    uint64_t limitExpandSkipped = 0;
    // Listings of the springs a pass or the tethers moved over the limit that ran eight springs at a
    // time (AVX2, one thread listing; src/core/step/limit_expand.h): the same lists as the scalar loop.
    uint64_t limitListingsAvx2 = 0;
    // Springs (structural and bend-shear) of the last spring phase that ran in groups of eight
    // evenly spaced ones (src/core/step/spring_groups.h), and their kernel ("avx2", "sse2" or
    // "generic": none grouped).
    uint64_t groupedSprings = 0;
    // Bend-shear springs whose force the last spring phase computed in the entry of another with
    // the same ends and rest length (their stiffness and damping summed; src/core/step/springs.cpp).
    uint64_t mergedSprings = 0;
    const char* springKernel = "generic";
    void reset() { *this = StepProfile{}; }
};

struct Ball {
    Vec3 x = Vec3::Zero();
    Vec3 v = Vec3::Zero();
    float radius = 0.5f; // m
    float mass = 2.f;    // kg; 0: immovable
    // Sleep (src/core/step/ball_sleep.cpp): a ball at rest with no moving cloth within its reach is
    // not simulated (asleep, velocity 0) until something can move it. The step sets and clears both;
    // code that moves a ball from outside the step clears `asleep` (or calls World::wake()), and a
    // sleeping ball given a velocity wakes by itself.
    uint16_t stillFrames = 0; // frames in a row it moved slower than sleep.speed (saturating)
    bool asleep = false;
};

// Moves a set of particles at a constant velocity (pinned while driven): the pull and tension scenes,
// and the app's drag tool, use this.
struct Driver {
    std::vector<Index> particles;
    Vec3 velocity = Vec3::Zero(); // m/s
};

struct StepState; // src/core/step/step_state.h: the step's caches and work arrays
// Owns the World's StepState. A copied World copies it (caches stay valid for the copied cloth; the
// implicit integrator's matrix starts empty).
class StepStateBox {
public:
    StepStateBox();
    ~StepStateBox();
    StepStateBox(const StepStateBox& other);
    StepStateBox& operator=(const StepStateBox& other);
    StepStateBox(StepStateBox&&) noexcept;
    StepStateBox& operator=(StepStateBox&&) noexcept;
    StepState& operator*() const { return *state_; }
    StepState* operator->() const { return state_.get(); }

private:
    std::unique_ptr<StepState> state_;
};

// The stability guard's estimate of the largest stable sub-step of explicit integration for the
// material as set (before any spring is capped), s: Gershgorin's bound over each particle's
// springs, so the stiffest springs on the lightest particle decide it (src/core/step/stability.cpp).
// Infinite for the reference integrators.
double stableStepEstimate(const Cloth& cloth, const Settings& settings);

// The sub-step the stability guard asks for (World::step): the step at which every particle's
// springs are within the guard's budget (Gershgorin, 10 % inside stableStepEstimate's bound, with
// the air drag's share), for every particle except those that need a shorter step and together
// hold at most lightMassFraction of the cloth's mass (a tear's light midpoint particles get capped
// springs instead of the whole cloth more sub-steps). With `interacting` (a ball near the cloth or
// a hand moving it) or material.model = kes, the guard's conservative step instead: no longer than
// stableStepEstimate and short enough that no spring needs the guard's per-spring cap. With
// `dampingFree` the springs' damping is left out (semi-implicit Euler taking it implicitly,
// time.damping: then only the stiffness bounds the step).
double guardStepEstimate(const Cloth& cloth, const Settings& settings, double lightMassFraction,
                         bool interacting = false, bool dampingFree = false);
// guardStepEstimate with the springs' damping and without it (dampingFree), from one walk over the
// springs: time.damping = auto compares the two (World::step).
struct GuardSteps {
    double withDamping, dampingFree; // s
};
GuardSteps guardStepEstimates(const Cloth& cloth, const Settings& settings, double lightMassFraction,
                              bool interacting = false);
// The fraction World::step passes: the lightest 1% of the mass may get capped springs.
inline constexpr double kGuardLightMass = 0.01;
// What a sub-step with the damping taken implicitly (a second spring pass that reads only the
// velocities, a second integrator stage) costs in sub-steps with it explicit: time.damping = auto
// takes it implicitly where that many times its sub-steps are fewer than the explicit damping's.
// Instructions per sub-step (callgrind, one thread, the curtain at rest): 1.55 and 1.56 at 0.4 m,
// 33 and 65 a side, 1.49 / 1.48 / 1.575 at 2 m, 40 / 129 / 257; rounded up, so that auto turns to it
// only where it is the cheaper step (bench/README.md, "The springs' damping and the guard's step").
inline constexpr double kImplicitDampingCost = 1.6;

// Per particle, the summed stiffness k (N/m) and damping kd (N s/m) of the structural and
// bend-shear springs touching it, as the material asks for them (before the guard caps any): the
// Gershgorin row sums behind stableStepEstimate (with material.model = kes, the tensile law's largest
// tangent and the hinges instead of the bend-shear springs). Resizes k and kd to the particle count.
void springSumsPerParticle(const Cloth& cloth, const Settings& settings, std::vector<double>& k,
                           std::vector<double>& kd);

// The structural springs' stiffness and damping per unit weight as the material asks for them (N/m,
// N s/m): material.stretch_*, or with material.model = kes the tensile law's largest tangent over
// kesStrainRange, times kesGuardWeight (5 with forward Euler: its Rayleigh damping; kes.h) (the
// guard's and the spring cache's "asked for").
struct AskedStiffness {
    double stiffness; // N/m per unit weight
    double damping;   // N s/m per unit weight
};
AskedStiffness structuralAsked(const Settings& settings);

class World {
public:
    Settings settings;
    Cloth cloth;
    std::vector<Ball> balls;
    std::vector<Driver> drivers;
    StepProfile profile;
    TearLog tearLog;
    double time = 0;        // s, simulated
    uint64_t steps = 0;     // frames
    float maxStrain = 0;    // over structural springs, after the last sub-step
    int frameSubsteps = 0;  // sub-steps of the last frame (time.substeps, or more: see guardSubsteps)
    // What the stability guard took from the material in the last frame: springs whose stiffness
    // or damping it capped, and the smallest fractions of the stiffness and damping the user set
    // that any spring kept (0 springs, 1 and 1: the material as set). Explicit integrators only.
    size_t guardCappedSprings = 0;
    float guardStiffnessKept = 1, guardDampingKept = 1;
    float maxSpeed = 0;     // m/s, fastest particle after the last frame
    bool asleep = false;    // at rest and not simulated until something can touch it (step/sleep.cpp)
    uint64_t sleptFrames = 0; // frames skipped asleep
    bool finite = true;     // false once any NaN/Inf appeared in the state
    std::string nonFiniteWhere; // where the first non-finite value was seen: phase (with check.finite
                                // or in Debug builds, else the frame's end) and particle

    // Builds the cloth from settings.cloth (grid or irregular), pins it and resets the state.
    // For MeshType::Obj pass the mesh explicitly. Returns an error message or "".
    std::string rebuild();
    std::string rebuild(const MeshData& mesh);

    // Re-derives cached per-particle values after material settings changed (density -> masses).
    void applySettings();

    void pinByMode(PinMode mode);
    void step();    // one frame
    void substep(); // one sub-step of frameDt / time.substeps (exposed for tests and benchmarks)

    void wake(); // something moved the cloth from outside the step (tools, impulses): simulate again

    // Sub-steps the next frame takes: time.substeps, raised by the stability guard (when on, with
    // an explicit integrator) towards frameDt / stableStepEstimate(), at most time.max_substeps.
    int guardSubsteps();

    // Cuts the cloth along `stroke`, points (u, v) in metres in restFrame (knife.h), at once: called
    // between frames, never inside one, so no phase sees the topology change under it. At once rather
    // than queued for the tear phase: the caller (the knife tool, the runner's --cut) gets what was
    // cut or why the stroke was refused right away, and the cut is not subject to the tear phase's
    // per-sub-step cap (tear.max_per_step), which is for the physics' tears. Wakes the cloth; copies
    // of driven particles keep following their drivers, as after a tear. Counted in the tear log
    // (TearMode::Knife per spring, knifeCuts per stroke).
    CutResult cut(const std::vector<Vec2d>& stroke);

    // One-shot velocity change dv (m/s) along `direction` on the particles within `radius` of `center`.
    int applyImpulse(const Vec3& center, float radius, const Vec3& direction, float dv);

    // Takes the piece holding `triangle` (pieces.h: triangles joined through shared particles) out
    // of the cloth: its particles, springs and triangles go and the rest is renumbered in order
    // (the drivers' particles too). Between frames only; whoever holds a particle index lets go
    // first. Returns the triangles removed (0: no such triangle).
    size_t deletePiece(Index triangle);

    double kineticEnergy() const;
    double potentialEnergy() const; // gravity + springs

    MeshData restMesh; // the mesh the cloth was built from (for rebuilds and reports)
    MeshFrame restFrame; // knifeFrame of restMesh (set by rebuild): the frame of cut strokes

    // The step's internals (src/core/step/): only the core can use them (the type is incomplete here).
    const StepState& stepState() const { return *state_; }
    StepState& stepState() { return *state_; } // world files restore it (world_file_read.cpp)
    // The step's caches and work arrays start empty, as in a freshly built World (a restored
    // checkpoint or a loaded file: every cache is rebuilt from the state). The integrator's and
    // sleep's state are cleared too: whoever calls this puts them back.
    void resetStepState();

private:
    StepStateBox state_;
};

} // namespace clothtear
