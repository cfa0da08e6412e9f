// The springs: per-thread force buffers, the spring cache with the stability guard's caps, and the
// structural and bend-shear spring forces (kernels: kernels.h).
#include "kernels.h"
#include "parallel.h"
#include "phases.h"
#include "spring_caps.h"

#include "clothtear/kes.h"

#include <algorithm>

namespace clothtear {
namespace {

// Stability guard, per particle. Gershgorin (stability.cpp): semi-implicit Euler is stable while,
// for every particle p,
//   dt^2 w_p sum(k) / 2 + dt w_p sum(kd) + dt c_air < 1.
// Where a particle's springs add up past kParticleBudget (spring_caps.h), they are scaled down by
// the factor that brings it back (a spring takes the smaller factor of its two ends, so both ends
// end within the budget). The guard's sub-step (stability.cpp, guardStepEstimate) puts every
// particle but the lightest 1 % of the mass inside the budget, so with the linear material only
// those (a tear's midpoints) and cloths past time.max_substeps are scaled; the kes law's springs
// are capped one by one first (refreshSpringCache). It is also what keeps random safe parameter
// sets finite (tests/test_stability.cpp).
void guardParticleBudget(const Cloth& cloth, SpringCache& S, float dt, float dragPerMass) {
    const size_t n = cloth.particleCount(), count = S.a16.size();
    std::vector<float> load(n, 0.f);
    for (size_t e = 0; e < count; ++e) {
        const float term = 0.5f * dt * dt * S.k[e] + dt * S.kd[e];
        load[S.a16[e] / 16] += cloth.invMass[S.a16[e] / 16] * term;
        load[S.b16[e] / 16] += cloth.invMass[S.b16[e] / 16] * term;
    }
    const float room = std::max(0.f, kParticleBudget - dt * dragPerMass);
    bool any = false;
    for (size_t p = 0; p < n; ++p) {
        load[p] = load[p] > room ? room / load[p] : 1.f; // now the factor
        any |= load[p] < 1.f;
    }
    if (!any) return;
    for (size_t e = 0; e < count; ++e) {
        const float f = std::min(load[S.a16[e] / 16], load[S.b16[e] / 16]);
        S.k[e] *= f;
        S.kd[e] *= f;
    }
}

} // namespace

// Gravity and air friction are applied in the integrator, per particle, where the velocity is read
// anyway (a = g - (c / density) v: physical drag F = -c A v with A the particle's area share, the
// same acceleration at any resolution; Keserica's "10% per step" model is a factor there too).
// This phase only sizes the per-thread force buffers. They are zero between sub-steps: the
// integrator clears every entry it reads, so nothing here touches all particles.
void phaseForces(const StepContext& ctx, Cloth& cloth, StepState& state) {
    const size_t n = cloth.particleCount();
    const size_t threads = size_t(ctx.threads);
    auto& acc = state.threads.acc;
    if (acc.size() != threads) acc.resize(threads);
    for (auto& buffer : acc)
        if (buffer.size() != n) buffer.resize(n, Eigen::Vector4f::Zero());
    state.threads.range.assign(threads, {n, 0});
    state.packed.resize(n);
}

// The spring cache follows the topology revision, the cloth's arrays, the inverse masses (mass
// revision: a particle let go by a tool is capped from its first sub-step; one sub-step late, a
// torn-off sliver of 1e-15 kg went to 1e8 m/s in the soak), the material and dt.
//
// Order: within each block of 64 springs, entry 8q + j holds spring 8j + q of the block, so the
// springs of a SIMD group (4 or 8) come from places 8 springs apart in mesh order. Springs next
// to each other in mesh order share particles, and a group that adds into the same accumulator
// several times waits on its own stores (measured with groups of four: 5.2 ns per spring in mesh
// order, 3.3 interleaved). Blocks stay in mesh order, so a thread's chunk still touches a band.
void refreshSpringCache(const StepContext& ctx, const Cloth& cloth, StepState& state) {
    SpringCache& S = state.springs;
    if (S.stamp.fresh(ctx.revisions, SpringCache::kDeps) && S.perSpringCaps == ctx.perSpringCaps) return;
    const MaterialSettings& m = ctx.settings->material;
    const bool kes = m.model == MaterialModel::Kes;
    // kes: the structural springs follow the tensile law (kesWidth below) and hinges replace the
    // bend-shear springs (phaseSpringsKes); the guard caps the law's largest tangent.
    const bool bends = !kes && (m.bendStiffness > 0.f || m.bendDamping > 0.f);
    const auto [stretchAsked, stretchDampingAsked] = structuralAsked(*ctx.settings);
    const bool guard = ctx.settings->time.stabilityGuard;
    const float dt = ctx.dt;
    const size_t ns = cloth.springs.size(), nb = bends ? cloth.bends.size() : 0;
    for (auto* a : {&S.a16, &S.b16}) a->resize(ns + nb);
    S.index.resize(ns + nb);
    for (auto* a : {&S.rest, &S.k, &S.kd}) a->resize(ns + nb);
    S.structural = ns;
    const float kCap = kStiffnessCap / (dt * dt), kdCap = kDampingCap / dt;
    auto fill = [&](const std::vector<Spring>& springs, size_t count, size_t offset, float ks, float kds) {
        constexpr size_t kBlock = 64, kWays = 8, kLane = kBlock / kWays;
        for (size_t e = 0; e < count; ++e) {
            // Entry e of this kind takes spring i (a permutation within full blocks).
            const size_t base = e - e % kBlock, q = e % kBlock;
            const size_t i = base + kBlock <= count ? base + (q % kWays) * kLane + q / kWays : e;
            const Spring& s = springs[i];
            float k = ks * s.weight, damping = kds * s.weight;
            if (ctx.perSpringCaps) {
                const float w = cloth.invMass[s.a] + cloth.invMass[s.b];
                if (k * w > kCap) k = kCap / w;
                if (damping * w > kdCap) damping = kdCap / w;
            }
            S.a16[offset + e] = 16u * s.a;
            S.b16[offset + e] = 16u * s.b;
            S.index[offset + e] = Index(i);
            S.rest[offset + e] = s.rest;
            S.k[offset + e] = k;
            S.kd[offset + e] = damping;
        }
    };
    fill(cloth.springs, ns, 0, float(stretchAsked), float(stretchDampingAsked));
    fill(cloth.bends, nb, ns, m.bendStiffness, m.bendDamping);
    if (guard) guardParticleBudget(cloth, S, dt, ctx.dragPerMass);
    // What the guard took from the material, for the report and the stats pane.
    S.cappedSprings = 0;
    S.stiffnessKept = S.dampingKept = 1.f;
    if (guard)
        for (size_t e = 0; e < ns + nb; ++e) {
            const bool structural = e < ns;
            const Spring& s = structural ? cloth.springs[S.index[e]] : cloth.bends[S.index[e]];
            const float asked = (structural ? float(stretchAsked) : m.bendStiffness) * s.weight;
            const float askedDamping = (structural ? float(stretchDampingAsked) : m.bendDamping) * s.weight;
            const bool capped = S.k[e] < asked * (1.f - 1e-6f) || S.kd[e] < askedDamping * (1.f - 1e-6f);
            S.cappedSprings += capped;
            if (asked > 0.f) S.stiffnessKept = std::min(S.stiffnessKept, S.k[e] / asked);
            if (askedDamping > 0.f) S.dampingKept = std::min(S.dampingKept, S.kd[e] / askedDamping);
        }
    S.kes = kes;
    S.perSpringCaps = ctx.perSpringCaps;
    S.kesWidth.clear();
    if (kes) {
        S.kesWidth.resize(ns);
        for (size_t e = 0; e < ns; ++e) {
            const Spring& s = cloth.springs[S.index[e]];
            const float asked = float(stretchAsked) * s.weight;
            const float kept = asked > 0.f ? std::min(1.f, S.k[e] / asked) : 1.f;
            S.kesWidth[e] = s.weight * s.rest * kept;
        }
    }
    S.maxRest = 0.f;
    for (size_t e = 0; e < ns; ++e) S.maxRest = std::max(S.maxRest, S.rest[e]);
    S.threadRange.clear(); // recomputed for the thread count in use
    S.stamp.set(ctx.revisions);
}

// Structural and bend-shear springs, scattered into per-thread buffers, summed in the integrator.
// Each thread first packs its share of the particles (PackedParticle: x and v in one cache line),
// then takes the same share of both kinds of springs (one contiguous chunk of each). Springs are
// built in mesh order, so a thread's chunks touch a band of the cloth and the bands of two threads
// overlap in a few rows; the integrator reads (and clears) a buffer only over its thread's band.
//
// Stability guard (time.stability_guard, on by default): explicit integration of a spring is stable
// only while k (1/m_a + 1/m_b) dt^2 stays small. Tearing halves triangles again and again (a midpoint
// particle gets 1/6 of a normal particle's mass on springs of twice the weight), and a finer mesh has
// lighter particles; instead of exploding, each spring's stiffness and damping are capped to
//   k (1/m_a + 1/m_b) dt^2 <= 1/3   and   kd (1/m_a + 1/m_b) dt <= 1/6,
// which keeps a particle with ~8 springs inside the stable region of semi-implicit Euler. A capped
// spring is softer than asked for; the Provot limit still holds its length. The capped constants
// are computed once per topology/material change (SpringCache), not per sub-step.
void phaseSprings(const StepContext& ctx, Cloth& cloth, StepState& state) {
    refreshSpringCache(ctx, cloth, state);
    SpringCache& S = state.springs;
    if (S.kes) {
        phaseSpringsKes(ctx, cloth, state);
        return;
    }
    const size_t n = cloth.particleCount();
    const size_t ns = S.structural, nb = S.a16.size() - S.structural;
    const int threads = int(state.threads.acc.size());
    const int nt = (threads > 1 && ns + nb >= kParallelWork) ? threads : 1;
    auto chunks = [&](int t) { return std::array<Chunk, 2>{chunkOf(ns, t, nt), chunkOf(nb, t, nt)}; };
    if (S.threadRange.size() != size_t(nt)) {
        S.threadRange.assign(nt, {n, 0});
        for (int t = 0; t < nt; ++t) {
            const auto c = chunks(t);
            size_t lo = n, hi = 0;
            auto widen = [&](size_t b, size_t e) {
                for (size_t i = b; i < e; ++i) {
                    lo = std::min<size_t>(lo, std::min(S.a16[i], S.b16[i]) / 16);
                    hi = std::max<size_t>(hi, std::max(S.a16[i], S.b16[i]) / 16 + 1);
                }
            };
            widen(c[0].begin, c[0].end);
            widen(ns + c[1].begin, ns + c[1].end);
            S.threadRange[t] = {lo, hi};
        }
    }
    for (int t = 0; t < nt; ++t) state.threads.range[t] = S.threadRange[t];
    const SpringArrays arrays{S.a16.data(), S.b16.data(), S.rest.data(), S.k.data(), S.kd.data()};
    const Vec3* x = cloth.x.data();
    const Vec3* v = cloth.v.data();
    PackedParticle* packed = state.packed.data();
    parallelRegion(ns + nb, nt, [&](int t, int nt2) {
        const Chunk pc = chunkOf(n, t, nt2);
        for (size_t p = pc.begin; p < pc.end; ++p) packed[p] = packedOf(x[p], v[p]);
        parallelBarrier(nt2);
        Eigen::Vector4f* acc = state.threads.acc[t].data();
        const auto c = chunks(t);
        springForces(arrays, c[0].begin, c[0].end, packed, acc);
        springForces(arrays, ns + c[1].begin, ns + c[1].end, packed, acc);
    });
}

} // namespace clothtear
