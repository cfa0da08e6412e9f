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

// Work arrays of the step, kept between steps so the step does not allocate.
struct StepScratch {
    std::vector<Vec3> force;                  // per particle
    std::vector<std::vector<Vec3>> threadAcc; // per thread scatter buffers
    std::vector<std::vector<float>> threadCount;
    std::vector<Vec3> correction;
    std::vector<TearCandidate> tearCandidates; // springs over their tear threshold, from the strain scan
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
    std::string nonFiniteWhere; // phase and particle of the first non-finite value

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
};

} // namespace clothtear
