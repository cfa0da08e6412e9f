// Revisions: the one mechanism by which the step's derived data (spring cache, limit cache, the
// stability guard's estimate, the implicit integrator's matrix, sleep) learns that what it was built
// from has changed. Each input has a revision counter; a cache remembers the revisions it was built
// for and is rebuilt when one it depends on moved. Nothing is hashed.
//
//   topology  cloth.topologyRevision: bumped by the tear module on every structural change
//   mass      cloth.massRevision: a new process-wide unique value whenever an inverse mass is set
//             (pins, tears, density, a freshly built cloth), so a cloth replaced by another never
//             shares a revision with it
//   material  bumped by the step when a material input of the caches changed (MaterialInputs below:
//             stiffness, damping, density, guard, air drag, integrator); settings are plain fields
//             a user may write at any time, so the step compares their values each sub-step
//   dt        bumped by the step when the sub-step length changed
//   drivers   bumped by the step when the set of particles the drivers hold changed
#pragma once
#include "clothtear/settings.h"
#include "clothtear/types.h"

#include <cstdint>
#include <vector>

namespace clothtear {

class World;
struct Driver;

struct Revisions {
    uint64_t topology = 0;
    uint64_t mass = 0;
    uint64_t material = 0;
    uint64_t dt = 0;
    uint64_t drivers = 0;
};

// What a cache depends on (a bit set of Revisions fields).
enum RevisionDeps : unsigned {
    kDependsOnTopology = 1u << 0,
    kDependsOnMass = 1u << 1,
    kDependsOnMaterial = 1u << 2,
    kDependsOnDrivers = 1u << 3,
    kDependsOnDt = 1u << 4,
};

// Carried by each cache: the revisions it was built for. A default stamp is stale.
struct CacheStamp {
    bool valid = false;
    Revisions built;
    bool fresh(const Revisions& now, unsigned deps) const {
        return valid && (!(deps & kDependsOnTopology) || built.topology == now.topology) &&
               (!(deps & kDependsOnMass) || built.mass == now.mass) &&
               (!(deps & kDependsOnMaterial) || built.material == now.material) &&
               (!(deps & kDependsOnDrivers) || built.drivers == now.drivers) &&
               (!(deps & kDependsOnDt) || built.dt == now.dt);
    }
    void set(const Revisions& now) {
        valid = true;
        built = now;
    }
};

// The settings the step's caches are derived from, compared by value.
struct MaterialInputs {
    MaterialSettings material;
    float density = 0.f;
    bool stabilityGuard = false;
    DampingMode damping = DampingMode::Explicit; // time.damping: the guard's step and caps may leave the damping out
    Integrator integrator = Integrator::SemiImplicitEuler;
    AirModel air = AirModel::Drag;
    float airDrag = 0.f;
    float kesStrain = 0.f; // kes: the strain range the guard takes the law's tangent over (kesStrainRange)
    bool operator==(const MaterialInputs& o) const;
};

// Observes the world's inputs once per sub-step and moves the revisions of those that changed.
class RevisionTracker {
public:
    // Updates the revisions from the world's inputs and returns them; with dt > 0 also for a
    // sub-step of that length.
    const Revisions& observe(const World& world, float dt = 0.f);
    const Revisions& now() const { return now_; }

private:
    Revisions now_;
    bool seenMaterial_ = false;
    MaterialInputs material_;
    float dt_ = 0.f;
    std::vector<std::vector<Index>> drivers_; // the particles each driver held when last observed
};

// A new process-wide unique revision value (Cloth::massRevision draws from it).
uint64_t nextUniqueRevision();

} // namespace clothtear
