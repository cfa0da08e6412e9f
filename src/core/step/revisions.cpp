// Revisions (revisions.h): value comparison of the inputs a user writes directly, counters for the rest.
#include "revisions.h"

#include "clothtear/kes.h"
#include "clothtear/world.h"

#include <atomic>

namespace clothtear {

bool MaterialInputs::operator==(const MaterialInputs& o) const {
    const MaterialSettings &a = material, &b = o.material;
    return a.density == b.density && a.stretchStiffness == b.stretchStiffness &&
           a.stretchDamping == b.stretchDamping && a.bendStiffness == b.bendStiffness &&
           a.bendDamping == b.bendDamping && a.model == b.model && a.kesT1 == b.kesT1 && a.kesT2 == b.kesT2 &&
           a.kesT3 == b.kesT3 && a.kesT4 == b.kesT4 && a.kesBendD == b.kesBendD && a.kesBendD1 == b.kesBendD1 &&
           a.kesBendAlpha == b.kesBendAlpha && kesStrain == o.kesStrain && density == o.density &&
           stabilityGuard == o.stabilityGuard && damping == o.damping && integrator == o.integrator && air == o.air &&
           airDrag == o.airDrag;
}

const Revisions& RevisionTracker::observe(const World& w, float dt) {
    now_.topology = w.cloth.topologyRevision;
    now_.mass = w.cloth.massRevision;
    MaterialInputs m;
    m.material = w.settings.material;
    m.density = w.cloth.density;
    m.stabilityGuard = w.settings.time.stabilityGuard;
    m.integrator = w.settings.time.integrator;
    m.damping = w.settings.time.damping;
    m.air = w.settings.air.model;
    m.airDrag = w.settings.air.dragCoefficient;
    m.kesStrain = w.settings.material.model == MaterialModel::Kes ? float(kesStrainRange(w.settings)) : 0.f;
    if (!seenMaterial_ || !(m == material_)) {
        material_ = m;
        seenMaterial_ = true;
        ++now_.material;
    }
    if (dt > 0.f && dt != dt_) {
        dt_ = dt;
        ++now_.dt;
    }
    bool same = drivers_.size() == w.drivers.size();
    for (size_t d = 0; same && d < drivers_.size(); ++d) same = drivers_[d] == w.drivers[d].particles;
    if (!same) {
        drivers_.resize(w.drivers.size());
        for (size_t d = 0; d < drivers_.size(); ++d) drivers_[d] = w.drivers[d].particles;
        ++now_.drivers;
    }
    return now_;
}

uint64_t nextUniqueRevision() {
    // The only process-wide state of the core: a counter, so that two cloths never share a mass
    // revision (a cache built for one is then never taken for the other).
    static std::atomic<uint64_t> counter{0};
    return counter.fetch_add(1, std::memory_order_relaxed) + 1;
}

} // namespace clothtear
