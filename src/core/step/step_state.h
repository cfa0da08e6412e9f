// The step's own state behind the World facade: caches derived from the cloth and the settings
// (rebuilt through revisions.h), work arrays kept between steps so the step does not allocate, and
// the little integrator and sleep state that outlives a sub-step. Internal to the core.
#pragma once
#include "clothtear/kes.h"
#include "clothtear/tear.h"
#include "clothtear/world.h"
#include "revisions.h"
#include "spring_groups.h"
#include "uninitialized_vector.h"

#include <array>
#include <memory>
#include <vector>

namespace clothtear {

// A ball touching a triangle in the collide phase: the side of the triangle (sign along its normal)
// the ball centre belongs on, which the contact phase keeps, and where the corners were left, which
// tells the contact phase whether the limit pulled them back since.
struct BallContact {
    Index triangle;
    uint32_t ball;
    int8_t side;
    std::array<Vec3, 3> at;
};

// Springs the limit works on (its lists), grown by expand without zero-filling.
using SpringList = UninitializedVector<Index>;

// A particle as the spring kernels read it (kernels.h): position and velocity, each xyz and a zero
// fourth lane; two to a cache line.
struct alignas(32) PackedParticle {
    float x[4];
    float v[4];
};
inline PackedParticle packedOf(const Vec3& x, const Vec3& v) {
    return PackedParticle{{x.x(), x.y(), x.z(), 0.f}, {v.x(), v.y(), v.z(), 0.f}};
}

// The springs as the kernels read them (springs.cpp, kernels.h): structural, then bend-shear, one
// array per field, ends as byte offsets (16 * particle), stiffness and damping after the stability
// guard, in an order that keeps the springs of a SIMD group apart (see refreshSpringCache).
struct SpringCache {
    static constexpr unsigned kDeps = kDependsOnTopology | kDependsOnMass | kDependsOnMaterial | kDependsOnDt;
    CacheStamp stamp;
    std::vector<uint32_t> a16, b16;  // 16 * particle index of the two ends
    std::vector<Index> index;        // the spring's index in cloth.springs / cloth.bends (a merged
                                     // bend-shear entry's: its first copy's; springs.cpp)
    float maxRest = 0;               // m, longest structural rest length (ball broad phase)
    std::vector<float> rest, k, kd;  // m, N/m, N s/m
    std::vector<uint32_t> entryOf;   // per structural spring: its entry (capTensionUnderBall reads its k)
    // material.model = kes: per structural entry, the width the tension per unit width acts on
    // (weight x rest: the adjacent rest area over the rest length), times what the guard kept of
    // the law's stiffness; k then holds the law's largest tangent (kesStrainRange) x weight, capped.
    std::vector<float> kesWidth;     // m
    bool kes = false;                // built for the kes model (no bend-shear entries)
    bool perSpringCaps = false;      // built with the per-spring caps (StepContext::perSpringCaps)
    // Built for the damping taken implicitly (StepContext::implicitDamping, integrate.cpp):
    // per particle the sum of its entries' kd (N s/m; an upper bound of its damping block's largest
    // eigenvalue).
    bool implicitDamping = false;
    std::vector<float> dampingSum;
    size_t structural = 0;           // entries [0, structural) are structural, the rest bend-shear
    // Groups of eight evenly spaced springs (spring_groups.h) and the bands of each kind (entries
    // and group indices absolute): groups and bands [0, structural*) are structural, the rest
    // bend-shear.
    std::vector<SpringGroup> groups;
    std::vector<SpringBand> bands;
    size_t structuralGroups = 0, structuralBands = 0;
    GroupKernel groupKernel = GroupKernel::None;
    size_t groupedSprings = 0; // springs of the cloth whose forces the groups compute (merged copies counted)
    size_t mergedSprings = 0;  // bend-shear springs whose force another's entry computes (springs.cpp)
    std::vector<std::array<size_t, 2>> threadRange; // per thread: particles [lo, hi) its chunk touches
    // What the stability guard took from the material (World::guardCappedSprings reports it):
    // springs whose stiffness or damping it capped, and the smallest fraction of the asked-for
    // stiffness and damping any spring kept (1: none capped).
    size_t cappedSprings = 0;
    float stiffnessKept = 1, dampingKept = 1;
};

// Tether sets: the nearest anchor's, and one to each end of the anchors' span (tethers.h).
inline constexpr int kTetherSets = 3;

// One set of tethers (tethers.h): each particle's anchor in the set, the rest length of a spring
// path to it, and the path itself as parents (for the tethers a tearing spring must stop).
struct TetherSet {
    std::vector<Index> tether; // per particle: its anchor if it has a tether to pull (not pinned), else kNone
    std::vector<float> length; // m, per particle: rest length of the spring path to the anchor
    std::vector<Index> parent; // per particle: previous particle on that path (kNone for anchors)
    std::vector<Index> order;  // particles reached, breadth-first from the anchors (parents first)
    std::vector<uint8_t> cut;  // per particle, this sub-step: its path runs through a tearing spring
};

// Per-topology data of the limit phase (limit.cpp, tethers.h) and its per-sub-step work arrays.
// Tether anchors are the pinned particles no driver moves, so it depends on the drivers too.
struct LimitCache {
    static constexpr unsigned kDeps = kDependsOnTopology | kDependsOnMass | kDependsOnDrivers;
    CacheStamp stamp;
    // Tethers (long-range attachments): tethers[0] to the nearest anchor, then one set to each end
    // of the anchors' span (tethers.h); sets without anchors are empty.
    std::array<TetherSet, kTetherSets> tethers;
    uint32_t depth = 0;        // springs from the anchors to the farthest particle reached
    float meanRest = 0;        // m, mean rest length of the structural springs
    // Structural springs of particle p: entries springStart[p] .. springStart[p + 1] of three arrays,
    // each spring with its other end and rest length (what the limit's listing and the tethers'
    // search read, without the spring). Three arrays, not one of structs: the AVX2 listing
    // (limit_expand.h) loads eight entries of each at once; kEndsPadding entries (spring 0,
    // particle 0, rest 0) follow the last row, so that it may load past a row's end.
    static constexpr size_t kEndsPadding = 8;
    std::vector<uint32_t> springStart;
    std::vector<Index> endSpring, endOther;
    std::vector<float> endRest; // m
    // Per particle: its bin of rest position, kRegionBins of equal width along the axis whose bins
    // follow the numbering best (buildRegionBins, only where Gauss-Seidel runs on several threads;
    // limit.cpp, regionPasses: its regions are runs of bins). By rest position, not by index, so
    // that a tear's new particles (appended last) fall in their neighbours' bin.
    static constexpr uint32_t kRegionBins = 64;
    std::vector<uint8_t> regionBin;
    // Work arrays, sized with the cloth.
    std::vector<uint32_t> moved; // per particle: the Jacobi pass (stamp) that last moved it
    // `listed` and `touched` have kFlagPadding zero bytes after their last entry: the AVX2 listing
    // (limit_expand.h) reads each flag as the low byte of a 32-bit word.
    static constexpr size_t kFlagPadding = 3;
    // Per structural spring: on a list of the passes (all 0 between sub-steps).
    std::vector<uint8_t> listed;
    // Per particle, during the limit phase: 1 where kTouched is set (the corners of the ball
    // contacts and the stretch band), else 0 (all 0 between limit phases): the AVX2 listing's copy
    // of the flag.
    std::vector<uint8_t> touched;
    // Per structural spring: a tear candidate of this sub-step's scan, which the passes leave alone
    // (all 0 between sub-steps).
    std::vector<uint8_t> candidate;
    uint32_t passStamp = 0;      // last pass stamp used
    // Sub-steps before the limit tries its expand prefilter again after one that found springs over
    // the limit (limit.cpp, prefilterPays: a hand dragging the cloth sideways makes every tether
    // pull put some over, and the scan is then wasted). Only speed depends on it, never a result.
    uint32_t prefilterWait = 0;
};

struct ImplicitEulerCache; // implicit_euler.h
// The implicit integrator's matrix and pattern: copying a World starts the copy with an empty one.
struct ImplicitCacheSlot {
    static constexpr unsigned kDeps = kDependsOnTopology | kDependsOnMass;
    CacheStamp stamp;
    std::unique_ptr<ImplicitEulerCache> cache;
    ImplicitCacheSlot();
    ~ImplicitCacheSlot();
    ImplicitCacheSlot(const ImplicitCacheSlot&);
    ImplicitCacheSlot& operator=(const ImplicitCacheSlot&);
};

// The triangles as the wind kernel reads them (wind.cpp): corners as byte offsets (16 * particle,
// as the spring cache), the area the wind may catch (twice the rest area: a sliver torn to nothing
// must not catch more than its share) and the corners' largest inverse mass (the guard's cap).
struct WindTriangle {
    uint32_t p16[3];
    float areaCap; // m^2
    float wMax;    // 1/kg
};
struct WindCache {
    static constexpr unsigned kDeps = kDependsOnTopology | kDependsOnMass;
    CacheStamp stamp;
    std::vector<WindTriangle> triangles;
    std::vector<std::array<size_t, 2>> threadRange; // per thread: particles [lo, hi) its chunk touches
};

// The stability guard's estimate of the stable sub-step (stability.cpp), cached: one for the frames
// that do not interact (the step within the particle budget) and one for those that do (the step
// without per-spring caps, step.cpp), each computed the first time a frame of its kind needs it.
struct GuardCache {
    static constexpr unsigned kDeps = kDependsOnTopology | kDependsOnMass | kDependsOnMaterial;
    struct Estimate {
        bool known = false, freeKnown = false;
        double step = 0;     // s, with the springs' damping
        double freeStep = 0; // s, with it left out (time.damping implicit or auto)
    };
    CacheStamp stamp;
    Estimate resting, interacting;
};

// What sleep.cpp remembers of the cloth it put to sleep.
struct SleepState {
    double restSince = -1; // s, simulated time since which the cloth is at rest; -1: moving
    Settings settings;     // the parameters when it fell asleep (any change wakes it)
    uint64_t topology = 0, mass = 0;
    Vec3 lo = Vec3::Zero(), hi = Vec3::Zero(); // m, the cloth's box
    std::vector<Vec3> frameStart;             // positions at the start of the frame, with sleep on
    // Torn pieces (piece_sleep.cpp): frames in a row each particle moved slower than sleep.speed
    // (saturating), and the parameters at the last frame (a change wakes the pieces).
    std::vector<uint16_t> stillFrames;
    Settings pieceSettings;
    // Balls (ball_sleep.cpp): their positions at the start of the frame, and the parameters at the
    // last frame (a change wakes a sleeping ball).
    std::vector<Vec3> ballFrameStart;
    Settings ballSettings;
    // Cache: the pieces as particle labels (pieces.h pieceLabels) for this topology revision.
    std::vector<Index> labels;
    uint64_t labelsTopology = 0;
    size_t labelCount = 0;
};

// Per-thread work arrays of the step (threads: see threadsFor in step_context.h).
struct ThreadBuffers {
    std::vector<std::vector<Eigen::Vector4f>> acc;  // force buffers (xyz), zero between sub-steps
    std::vector<std::array<size_t, 2>> range;       // particles [lo, hi) each force buffer may hold
    // The spring groups' forces (spring_groups.h), per thread, over the same range as acc; zero
    // between sub-steps. groupForcesSet: the spring phase wrote them this sub-step.
    std::vector<ComponentArrays> groupForces;
    bool groupForcesSet = false;
    std::vector<std::vector<Eigen::Vector4f>> corr; // limit corrections (xyz, count), zero between passes
    std::vector<std::vector<Eigen::Vector4f>> corrV; // limit velocity changes (xyz)
    std::vector<SpringList> active;                 // springs the limit still works on
    // Gauss-Seidel on several threads (limit.cpp, regionPasses): per thread, its list split by
    // region (one per thread), then the springs joining two regions.
    std::vector<std::vector<SpringList>> regionLists;
    std::vector<std::vector<Index>> touched;        // particles with a correction this pass
    std::vector<std::vector<Index>> moved;          // particles the last Jacobi pass moved
    std::vector<std::vector<TearCandidate>> found;  // tear candidates of the scan
    std::vector<std::vector<Index>> held;           // springs over a tear threshold the scan kept off
                                                    // the candidates: a flap's spokes (isFlapSpoke)
                                                    // and one-step overshoots (limit.cpp)
};

struct StepState {
    RevisionTracker revisions;
    SpringCache springs;
    LimitCache limit;
    GuardCache guard;
    WindCache wind;
    ImplicitCacheSlot implicit;
    ThreadBuffers threads;
    std::vector<PackedParticle> packed;         // per particle: x and v for the spring kernels
    ComponentArrays components;                 // x and v by component, for the groups' kernel
    std::vector<TearCandidate> tearCandidates;  // springs over their tear threshold, from the scan
    std::vector<BallContact> contacts;          // from the collide phase, for the contact phase
    std::vector<int32_t> contactOf;             // per triangle: its entry in contacts, -1
    // The fabric a ball stretches beyond its contacts this sub-step (limit_ball.cpp, markStretchBand),
    // per particle its rest distance from them (infinite outside the band, between sub-steps), and
    // the search's queue.
    std::vector<Index> stretchBand;
    std::vector<float> bandDistance;
    std::vector<Index> bandQueue;
    std::vector<Vec3> externalForce;            // reference integrators: N per particle (wind)
    std::vector<Vec3> xpbdDx;                   // XPBD: displacements within the sub-step
    std::vector<Vec3d> kesHingeForce;           // kes: the hinges' forces of this sub-step (N)
    std::vector<HingeTangent> kesHingeTangents; // kes, implicit Euler: the hinges linearized
    // Verlet (integrate.cpp): whether the last integration was Verlet (else its next step starts
    // it) and per particle, a dt / 2 of its last step. Part of the state hash.
    bool verletRunning = false;
    std::vector<Vec3> verletKick;
    int substepsNow = 0; // sub-steps of the frame being stepped (0 outside step(): time.substeps)
    // This frame a ball is near the cloth or a hand (driver) moves: the guard takes its conservative
    // step and caps springs one by one (step.cpp, World::guardSubsteps).
    bool interacting = false;
    // This frame takes the springs' damping implicitly under time.damping = auto: the guard chose it
    // (World::guardSubsteps) because the explicit damping's step would be past time.max_substeps
    // or its sub-steps would cost more (implicitDampingNow).
    bool dampingImplicit = false;
    SleepState sleep;
};

} // namespace clothtear
