// The world: one cloth, balls, kinematic drivers, settings, and the step.
//
// A frame is `time.substeps` sub-steps. Each sub-step runs named phases, each timed into StepProfile:
//   forces -> springs -> wind -> integrate -> limit -> collide -> tear -> bookkeeping
// A phase the scene does not need is not entered (no wind: no wind loop; no balls and no ground: no
// collision loop; tearing off: no strain scan). Topology changes (tearing) happen only in the tear
// phase, between the others.
#pragma once
#include "clothtear/cloth.h"
#include "clothtear/settings.h"
#include "clothtear/tear.h"
#include "clothtear/tear_events.h"
#include "clothtear/types.h"

#include <array>
#include <string>
#include <vector>

namespace clothtear {

enum class Phase : int { Forces, Springs, Wind, Integrate, Limit, Collide, Tear, Bookkeeping, Count };
const char* phaseName(Phase p);

struct StepProfile {
    std::array<double, int(Phase::Count)> ms{};     // accumulated milliseconds per phase
    std::array<uint64_t, int(Phase::Count)> runs{}; // how often each phase was entered
    uint64_t substeps = 0;
    void reset() { *this = StepProfile{}; }
};

struct Ball {
    Vec3 x = Vec3::Zero();
    Vec3 v = Vec3::Zero();
    float radius = 0.5f; // m
    float mass = 2.f;    // kg
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
    std::vector<float> rest, k, kd;  // m, N/m, N s/m
    size_t structural = 0;           // entries [0, structural) are structural, the rest bend-shear
    std::vector<std::array<size_t, 2>> threadRange; // per thread: particles [lo, hi) its chunk touches
    uint64_t key = ~uint64_t(0);
};

// Work arrays of the step, kept between steps so the step does not allocate.
struct StepScratch {
    std::vector<std::vector<Eigen::Vector4f>> threadAcc; // per thread force buffers (xyz), zero between sub-steps
    std::vector<TearCandidate> tearCandidates; // springs over their tear threshold, from the strain scan
    // Hot-loop state (world.cpp, [SPRINGS] and [LIMIT]).
    std::vector<std::array<size_t, 2>> threadRange; // per thread: particles [lo, hi) its buffer may hold
    std::vector<std::vector<Eigen::Vector4f>> threadCorr; // per thread: limit corrections (xyz, count)
    std::vector<std::vector<Index>> threadActive;   // per thread: springs the limit still works on
    std::vector<std::vector<Index>> threadTouched;  // per thread: particles with a correction this pass
    std::vector<std::vector<Index>> threadMoved;    // per thread: particles the last Jacobi pass moved
    std::vector<std::vector<TearCandidate>> threadFound; // per thread: tear candidates of the scan
    std::vector<PackedParticle> packed; // per particle: x and v for the spring kernels
    uint64_t pinSignature = 0; // hash of the particles with invMass 0, from the last integration
    SpringCache springs;
    LimitCache limit;
};

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
    void substep(); // one sub-step (exposed for tests and benchmarks)

    // One-shot velocity change dv (m/s) along `direction` on the particles within `radius` of `center`.
    int applyImpulse(const Vec3& center, float radius, const Vec3& direction, float dv);

    double kineticEnergy() const;
    double potentialEnergy() const; // gravity + springs

    MeshData restMesh; // the mesh the cloth was built from (for rebuilds and reports)

private:
    StepScratch scratch_;
    void phaseForces(float dt);
    void phaseSprings(float dt);
    void phaseWind();
    void phaseIntegrate(float dt);
    void phaseLimit(float dt);
    void phaseCollide(float dt);
    void phaseTear();
    void phaseBookkeeping();
    void moveDrivers(float dt);
    void refreshLimitCache();
    void refreshSpringCache(float dt);
    void checkFinite(int afterPhase);
};

} // namespace clothtear
