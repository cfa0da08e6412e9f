// The world: one cloth, balls, kinematic drivers, settings, and the step.
//
// A frame is `time.substeps` sub-steps. Each sub-step runs named phases, each timed into StepProfile:
//   forces -> springs -> wind -> integrate -> collide -> limit -> contact -> tear -> bookkeeping
// A phase the scene does not need is not entered (no wind: no wind loop; no balls: no collide
// phase, and no contact phase without the ground either; tearing off: no strain scan). Topology
// changes (tearing) happen only in the tear phase, between the others.
#pragma once
#include "clothtear/cloth.h"
#include "clothtear/settings.h"
#include "clothtear/tear.h"
#include "clothtear/tear_events.h"
#include "clothtear/types.h"

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace clothtear {

enum class Phase : int { Forces, Springs, Wind, Integrate, Collide, Limit, Contact, Tear, Bookkeeping, Count };
const char* phaseName(Phase p);

struct StepProfile {
    std::array<double, int(Phase::Count)> ms{};     // accumulated milliseconds per phase
    std::array<uint64_t, int(Phase::Count)> runs{}; // how often each phase was entered
    uint64_t substeps = 0;
    uint64_t solverIterations = 0; // implicit Euler: conjugate-gradient iterations, summed
    // Length limit not converged: sub-steps whose last allowed pass (limit.iterations) still
    // corrected springs, and those springs, summed. The cloth then ends the sub-step stretched past
    // the limit (e.g. a fine cloth in wind at few sub-steps: README "Status and known gaps").
    uint64_t limitCapped = 0;
    uint64_t limitCappedSprings = 0;
    void reset() { *this = StepProfile{}; }
};

struct Ball {
    Vec3 x = Vec3::Zero();
    Vec3 v = Vec3::Zero();
    float radius = 0.5f; // m
    float mass = 2.f;    // kg; 0: immovable
};

// A ball touching a triangle in the collide phase: the side of the triangle (sign along its normal)
// the ball centre belongs on, which the contact phase keeps, and where the corners were left, which
// tells the contact phase whether the limit pulled them back since.
struct BallContact {
    Index triangle;
    uint32_t ball;
    int8_t side;
    std::array<Vec3, 3> at;
};

// Moves a set of particles at a constant velocity (pinned while driven): the pull and tension scenes,
// and the app's drag tool, use this.
struct Driver {
    std::vector<Index> particles;
    Vec3 velocity = Vec3::Zero(); // m/s
};

// Per-topology data of the limit phase (world.cpp [LIMIT], src/core/tethers.h), rebuilt when the
// topology or the set of anchors changes, and its per-sub-step work arrays.
struct LimitCache {
    // Tethers (long-range attachments).
    std::vector<Index> anchor; // per particle: the pinned particle it hangs from, kNone if none
    std::vector<Index> tether; // per particle: its anchor if it has a tether to pull (not pinned), else kNone
    std::vector<float> length; // m, per particle: rest length of the spring path to the anchor
    std::vector<Index> parent; // per particle: previous particle on that path (kNone for anchors)
    std::vector<Index> order;  // particles reached, breadth-first from the anchors (parents first)
    uint32_t depth = 0;        // springs from the anchors to the farthest particle reached
    float meanRest = 0;        // m, mean rest length of the structural springs
    // Structural springs of particle p: springOf[springStart[p] .. springStart[p + 1]).
    std::vector<uint32_t> springStart;
    std::vector<Index> springOf;
    uint64_t key = ~uint64_t(0); // what this was built for (topology revision, anchors); ~0: stale
    // Work arrays, sized with the cloth.
    std::vector<uint8_t> cut;    // per particle: its tether path runs through a tearing spring
    std::vector<uint32_t> moved; // per particle: the Jacobi pass (stamp) that last moved it
    std::vector<uint8_t> listed; // per structural spring: on a Jacobi list (all 0 between sub-steps)
    uint32_t stamp = 0;          // last pass stamp used
};

// A particle as the spring kernels read it (src/core/step_kernels.h): position and velocity, each
// xyz and a zero fourth lane; two to a cache line.
struct alignas(32) PackedParticle {
    float x[4];
    float v[4];
};

// The springs as the kernels read them (world.cpp [SPRINGS], step_kernels.h): structural, then
// bend-shear, one array per field, ends as byte offsets (16 * particle), stiffness and damping
// after the stability guard, in an order that keeps the springs of a SIMD group apart (see
// refreshSpringCache). Rebuilt when the topology, the pinned particles, the material or dt change.
struct SpringCache {
    std::vector<uint32_t> a16, b16;  // 16 * particle index of the two ends
    std::vector<Index> index;        // the spring's index in cloth.springs / cloth.bends
    float maxRest = 0;               // m, longest structural rest length (ball broad phase)
    std::vector<float> rest, k, kd;  // m, N/m, N s/m
    size_t structural = 0;           // entries [0, structural) are structural, the rest bend-shear
    std::vector<std::array<size_t, 2>> threadRange; // per thread: particles [lo, hi) its chunk touches
    uint64_t key = ~uint64_t(0);
};

struct ImplicitEulerCache; // src/core/implicit_euler.h
// The implicit integrator's matrix and pattern. A cache that can be rebuilt at any time: a copied
// World starts with an empty one.
struct ImplicitCacheHolder {
    std::unique_ptr<ImplicitEulerCache> cache;
    ImplicitCacheHolder();
    ~ImplicitCacheHolder();
    ImplicitCacheHolder(const ImplicitCacheHolder&);
    ImplicitCacheHolder& operator=(const ImplicitCacheHolder&);
    ImplicitCacheHolder(ImplicitCacheHolder&&) noexcept;
    ImplicitCacheHolder& operator=(ImplicitCacheHolder&&) noexcept;
};

// Work arrays of the step, kept between steps so the step does not allocate.
struct StepScratch {
    std::vector<std::vector<Eigen::Vector4f>> threadAcc; // per thread force buffers (xyz), zero between sub-steps
    std::vector<TearCandidate> tearCandidates; // springs over their tear threshold, from the strain scan
    // Hot-loop state (world.cpp, [SPRINGS] and [LIMIT]).
    std::vector<std::array<size_t, 2>> threadRange; // per thread: particles [lo, hi) its buffer may hold
    std::vector<std::vector<Eigen::Vector4f>> threadCorr; // per thread: limit corrections (xyz, count)
    std::vector<std::vector<Eigen::Vector4f>> threadCorrV; // per thread: limit velocity changes (xyz)
    std::vector<std::vector<Index>> threadActive;   // per thread: springs the limit still works on
    std::vector<std::vector<Index>> threadTouched;  // per thread: particles with a correction this pass
    std::vector<std::vector<Index>> threadMoved;    // per thread: particles the last Jacobi pass moved
    std::vector<std::vector<TearCandidate>> threadFound; // per thread: tear candidates of the scan
    std::vector<PackedParticle> packed; // per particle: x and v for the spring kernels
    std::vector<BallContact> contacts; // from the collide phase, for the contact phase
    std::vector<int32_t> contactOf;    // per triangle: its entry in contacts, -1 (scratch of the contact phase)
    uint64_t pinSignature = 0; // hash of the particles with invMass 0, from the last integration
    bool verletRunning = false; // the last integration was Verlet (else its next step starts it)
    std::vector<Vec3> verletKick; // Verlet: per particle, a dt / 2 of its last step (world.cpp [INTEGRATE])
    SpringCache springs;
    LimitCache limit;
    // Reference integrators (implicit Euler, XPBD).
    std::vector<Vec3> externalForce; // N per particle from the wind phase
    std::vector<Vec3> xpbdDx;         // XPBD: displacements within the sub-step
    ImplicitCacheHolder implicit;
    std::vector<Vec3> frameStart; // positions at the start of the frame (sleep.cpp), with sleep on
};

// The stability guard's estimate of the largest stable sub-step of explicit integration for the
// material as set (before any spring is capped), s: Gershgorin's bound over each particle's
// springs, so the stiffest springs on the lightest particle decide it (src/core/stability.cpp).
// Infinite for the reference integrators.
double stableStepEstimate(const Cloth& cloth, const Settings& settings);

// Per particle, the summed stiffness k (N/m) and damping kd (N s/m) of the structural and
// bend-shear springs touching it, as the material asks for them (before the guard caps any): the
// Gershgorin row sums behind stableStepEstimate. Resizes k and kd to the particle count.
void springSumsPerParticle(const Cloth& cloth, const MaterialSettings& material, std::vector<double>& k,
                           std::vector<double>& kd);

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
    float maxSpeed = 0;     // m/s, fastest particle after the last frame
    bool asleep = false;    // at rest and not simulated until something can touch it (sleep.cpp)
    uint64_t sleptFrames = 0; // frames skipped asleep
    // Benchmark switch, not a parameter: false makes the ball phases test every triangle instead of
    // the particles near each ball (what the broad phase saves, bench/README.md).
    bool ballBroadPhase = true;
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

    // One-shot velocity change dv (m/s) along `direction` on the particles within `radius` of `center`.
    int applyImpulse(const Vec3& center, float radius, const Vec3& direction, float dv);

    double kineticEnergy() const;
    double potentialEnergy() const; // gravity + springs

    MeshData restMesh; // the mesh the cloth was built from (for rebuilds and reports)

private:
    StepScratch scratch_;
    int substepsNow_ = 0; // sub-steps of the frame being stepped (0 outside step(): time.substeps)
    uint64_t guardKey_ = ~uint64_t(0);
    // Sleep (sleep.cpp): when the cloth came to rest, and what it looked like when it fell asleep.
    double restSince_ = -1;
    uint64_t sleepSettingsHash_ = 0, sleepTopology_ = 0, sleepPins_ = 0;
    Vec3 sleepLo_ = Vec3::Zero(), sleepHi_ = Vec3::Zero(); // m, the cloth's box
    bool stayAsleep();  // asleep and nothing can touch the cloth this frame
    void updateSleep(); // after a frame: at rest long enough?
    float frameSpeed() const; // m/s, largest displacement of a particle over the last frame / frameDt
    float ballEdgeBound() const; // m, bound on every triangle edge this sub-step (ball broad phase)
    double guardStep_ = 0; // s, cached stableStepEstimate()
    void phaseForces(float dt);
    void phaseSprings(float dt);
    void phaseWind(float dt);
    void phaseIntegrate(float dt);
    void phaseIntegrateReference(float dt); // implicit Euler, XPBD (springs included)
    void phaseLimit(float dt);
    void phaseCollide(float dt);
    void phaseContact(float dt);
    void phaseTear();
    void phaseBookkeeping();
    void moveDrivers(float dt);
    void refreshLimitCache();
    void refreshSpringCache(float dt);
    void guardParticleBudget(float dt, float dragPerMass);
    float guardDragPerMass(float dt) const;
    void checkFinite(int afterPhase);
};

} // namespace clothtear
