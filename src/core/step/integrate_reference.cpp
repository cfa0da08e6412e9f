// The reference integrators in the step: implicit Euler (implicit_euler.h) and XPBD (xpbd.h), with
// the springs at their full stiffness and the wind phase's forces.
#include "implicit_euler.h"
#include "phases.h"
#include "xpbd.h"

namespace clothtear {

// The reference integrators (implicit_euler.h, xpbd.h): springs with their full stiffness (no
// stability guard), gravity, air and the wind phase's forces, summed out of (and cleared from) the
// per-thread buffers. Afterwards the packed copy and the pin signature are left as the explicit
// integrator leaves it, for the limit phase.
void phaseIntegrateReference(const StepContext& ctx, Cloth& cloth, StepState& state) {
    refreshSpringCache(ctx, cloth, state); // the strain scan reads its ends and rest lengths
    const Settings& settings = *ctx.settings;
    const float dt = ctx.dt;
    const size_t n = cloth.particleCount();
    std::vector<Vec3>& ext = state.externalForce;
    ext.clear();
    for (size_t t = 0; t < state.threads.acc.size(); ++t) {
        const auto [lo, hi] = state.threads.range[t];
        if (lo >= hi) continue;
        if (ext.empty()) ext.assign(n, Vec3::Zero());
        for (size_t p = lo; p < hi; ++p) {
            ext[p] += state.threads.acc[t][p].head<3>();
            state.threads.acc[t][p].setZero();
        }
    }
    const MaterialSettings& m = settings.material;
    // kes: with implicit Euler the structural springs follow the law inside the solve and the
    // hinges' forces come with their Jacobians (implicit_euler.h); with XPBD the law's forces enter
    // as external forces (explicit within its step: stable only at the steps an explicit integrator
    // needs; docs/kes-material.md), the springs keep their damping only.
    const bool kes = m.model == MaterialModel::Kes;
    const bool implicit = settings.time.integrator == Integrator::ImplicitEuler;
    const KesLaw law = kesLawSI(m);
    if (kes) kesForces(ctx, cloth, state, ext, implicit ? &state.kesHingeTangents : nullptr);
    static const std::vector<Spring> kNoSprings;
    // Implicit Euler treats air drag implicitly (stable at any value); XPBD applies it explicitly,
    // capped by the guard like the explicit integrators.
    const float drag = settings.time.integrator == Integrator::Xpbd ? ctx.dragPerMass
                                                                    : airDragPerMass(settings, cloth.density);
    ReferenceStepInput in{dt,
                          ctx.gravity,
                          drag,
                          ctx.keep,
                          {SpringKind{cloth.springs, kes ? 0.f : m.stretchStiffness, m.stretchDamping},
                           kes && implicit ? SpringKind{cloth.bends, 0.f, 0.f} // the hinges' (c, d) blocks
                           : SpringKind{kes ? kNoSprings : cloth.bends, m.bendStiffness, m.bendDamping}},
                          ext,
                          kes && implicit ? &law : nullptr,
                          kesStrainRange(settings),
                          kes && implicit ? std::span<const HingeTangent>(state.kesHingeTangents)
                                          : std::span<const HingeTangent>()};
    if (implicit) {
        ImplicitCacheSlot& slot = state.implicit;
        // The pattern follows the topology and the pinned particles: a stale cache starts afresh.
        if (!slot.cache || !slot.stamp.fresh(ctx.revisions, ImplicitCacheSlot::kDeps)) {
            slot.cache = std::make_unique<ImplicitEulerCache>();
            slot.stamp.set(ctx.revisions);
        }
        const ImplicitEulerOptions options{settings.time.cgTolerance, settings.time.cgMaxIterations};
        implicitEulerStep(cloth, in, options, *slot.cache);
        ctx.profile->solverIterations += uint64_t(slot.cache->lastIterations);
    } else {
        xpbdStep(cloth, in, state.xpbdDx);
    }
    for (Index p = 0; p < n; ++p)
        state.packed[p] = packedOf(cloth.x[p], cloth.v[p]);
    state.verletRunning = false;
    moveDrivers(ctx, cloth, state);
}

} // namespace clothtear
