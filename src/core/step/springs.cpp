// The springs: per-thread force buffers, the spring cache with the stability guard's caps, and the
// structural and bend-shear spring forces (kernels: kernels.h).
#include "env_switch.h"
#include "kernels.h"
#include "parallel.h"
#include "phases.h"
#include "spring_caps.h"
#include "spring_groups.h"
#include "uninitialized_vector.h"

#include "clothtear/kes.h"

#include <algorithm>
#include <string>

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
// With the damping taken implicitly (dampingFree) only the stiffness counts and is scaled.
void guardParticleBudget(const Cloth& cloth, SpringCache& S, float dt, float dragPerMass, bool dampingFree) {
    const size_t n = cloth.particleCount(), count = S.a16.size();
    std::vector<float> load(n, 0.f);
    const float dampingShare = dampingFree ? 0.f : dt;
    for (size_t e = 0; e < count; ++e) {
        const float term = 0.5f * dt * dt * S.k[e] + dampingShare * S.kd[e];
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
        if (!dampingFree) S.kd[e] *= f;
    }
}

// The packed copy of particles [b, e) of n, and with `components` their x, y, z, vx, vy, vz arrays.
void packParticles(size_t b, size_t e, size_t n, const Vec3* x, const Vec3* v, PackedParticle* packed,
                   float* const* components) {
    size_t p = b;
#if defined(__SSE2__)
    // A 16-byte load from a Vec3 takes the next particle's x too (masked off), so the last particle,
    // whose load would pass the end of the array, goes through the scalar loop.
    const __m128 xyz = _mm_castsi128_ps(_mm_setr_epi32(-1, -1, -1, 0));
    const size_t fast = std::min(e, n - 1);
    for (; p + 4 <= fast; p += 4) {
        __m128 X[4], V[4];
        for (int j = 0; j < 4; ++j) {
            X[j] = _mm_and_ps(xyz, _mm_loadu_ps(x[p + j].data()));
            V[j] = _mm_and_ps(xyz, _mm_loadu_ps(v[p + j].data()));
            _mm_store_ps(packed[p + j].x, X[j]);
            _mm_store_ps(packed[p + j].v, V[j]);
        }
        if (!components) continue;
        _MM_TRANSPOSE4_PS(X[0], X[1], X[2], X[3]);
        _MM_TRANSPOSE4_PS(V[0], V[1], V[2], V[3]);
        for (int c = 0; c < 3; ++c) {
            _mm_storeu_ps(components[c] + p, X[c]);
            _mm_storeu_ps(components[3 + c] + p, V[c]);
        }
    }
#endif
    for (; p < e; ++p) {
        packed[p] = packedOf(x[p], v[p]);
        if (components)
            for (int c = 0; c < 3; ++c) components[c][p] = x[p][c], components[3 + c][p] = v[p][c];
    }
}

// The packed velocities of particles [b, e) into the groups' vx, vy, vz arrays (`components`).
void packVelocities(size_t b, size_t e, const PackedParticle* packed, float* const* components) {
    size_t p = b;
#if defined(__SSE2__)
    for (; p + 4 <= e; p += 4) {
        __m128 V[4];
        for (int j = 0; j < 4; ++j) V[j] = _mm_load_ps(packed[p + j].v);
        _MM_TRANSPOSE4_PS(V[0], V[1], V[2], V[3]);
        for (int c = 0; c < 3; ++c) _mm_storeu_ps(components[c] + p, V[c]);
    }
#endif
    for (; p < e; ++p)
        for (int c = 0; c < 3; ++c) components[c][p] = packed[p].v[c];
}

// Bend-shear springs with the same two ends and the same rest length, merged into one entry of the
// cache: a grid's bend-shear springs that span two columns or two rows come twice (the two edges
// whose opposite corners are the same two particles; a third of the bend-shear springs of the 128 x
// 128 curtain), and one entry with their stiffness and damping summed gives their summed force for
// one spring's loads and arithmetic (to rounding: the force is added once instead of twice). The
// cloth keeps every spring; a tear removes one copy and the next rebuild merges what is left.
struct MergedSprings {
    std::vector<Spring> springs;  // one per distinct (ends, rest), as the first of its copies has it
    std::vector<uint32_t> start;  // springs[u]'s copies: copies[start[u], start[u + 1])
    std::vector<Index> copies;    // indices into the springs merged, in index order
};

// CLOTHTEAR_MERGE_SPRINGS=0: every bend-shear spring its own entry (tests compare the two).
bool mergeAllowed() { return envSwitchOn("CLOTHTEAR_MERGE_SPRINGS"); }

MergedSprings mergeSameSprings(const std::vector<Spring>& springs, size_t count, size_t particles, bool merge) {
    // The springs of one first end (the smaller index) are a particle's few: look for a copy among
    // those before it there (a counting sort by first end, stable, so in index order).
    // Arrays written before they are read are not zero-filled first (UninitializedVector).
    std::vector<uint32_t> firstStart(particles + 1, 0);
    UninitializedVector<uint32_t> byFirst(count);
    auto first = [&](size_t i) { return std::min(springs[i].a, springs[i].b); };
    auto second = [&](size_t i) { return std::max(springs[i].a, springs[i].b); };
    for (size_t i = 0; i < count; ++i) ++firstStart[first(i) + 1];
    for (size_t p = 1; p <= particles; ++p) firstStart[p] += firstStart[p - 1];
    {
        std::vector<uint32_t> at(firstStart.begin(), firstStart.end() - 1);
        for (size_t i = 0; i < count; ++i) byFirst[at[first(i)]++] = uint32_t(i);
    }
    UninitializedVector<uint32_t> leader(count); // the first spring of i's copies
    for (size_t p = 0; p < particles; ++p)
        for (uint32_t k = firstStart[p]; k < firstStart[p + 1]; ++k) {
            const uint32_t i = byFirst[k];
            leader[i] = i;
            for (uint32_t j = firstStart[p]; j < k; ++j) {
                const uint32_t o = byFirst[j];
                if (merge && leader[o] == o && second(o) == second(i) && springs[o].rest == springs[i].rest) {
                    leader[i] = o;
                    break;
                }
            }
        }
    MergedSprings out;
    UninitializedVector<uint32_t> unique(count); // per leader: its entry in out.springs (read only there)
    for (size_t i = 0; i < count; ++i)
        if (leader[i] == i) {
            unique[i] = uint32_t(out.springs.size());
            out.springs.push_back(springs[i]);
        }
    out.start.assign(out.springs.size() + 1, 0);
    for (size_t i = 0; i < count; ++i) ++out.start[unique[leader[i]] + 1];
    for (size_t u = 1; u < out.start.size(); ++u) out.start[u] += out.start[u - 1];
    out.copies.resize(count);
    std::vector<uint32_t> at(out.start.begin(), out.start.end() - 1);
    for (size_t i = 0; i < count; ++i) out.copies[at[unique[leader[i]]]++] = Index(i);
    return out;
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
// Order (groupSprings, spring_groups.h): per kind, band by band along the cloth, the band's groups
// of eight evenly spaced springs, then its other springs in mesh order (interleaved in blocks of 64
// so that a SIMD group of kernels.h does not add into one accumulator several times). A thread's
// chunk of the entries then touches a band of the cloth.
void refreshSpringCache(const StepContext& ctx, const Cloth& cloth, StepState& state) {
    SpringCache& S = state.springs;
    if (S.stamp.fresh(ctx.revisions, SpringCache::kDeps) && S.perSpringCaps == ctx.perSpringCaps &&
        S.implicitDamping == ctx.implicitDamping)
        return;
    const MaterialSettings& m = ctx.settings->material;
    const bool kes = m.model == MaterialModel::Kes;
    // kes: the structural springs follow the tensile law (kesWidth below) and hinges replace the
    // bend-shear springs (phaseSpringsKes); the guard caps the law's largest tangent.
    const bool bends = !kes && (m.bendStiffness > 0.f || m.bendDamping > 0.f);
    const AskedStiffness stretchAsked = structuralAsked(*ctx.settings);
    const bool guard = ctx.settings->time.stabilityGuard;
    const float dt = ctx.dt;
    const size_t ns = cloth.springs.size();
    const MergedSprings merged = mergeSameSprings(cloth.bends, bends ? cloth.bends.size() : 0, cloth.particleCount(), mergeAllowed());
    const size_t nb = merged.springs.size();
    for (auto* a : {&S.a16, &S.b16}) a->resize(ns + nb);
    S.index.resize(ns + nb);
    for (auto* a : {&S.rest, &S.k, &S.kd}) a->resize(ns + nb);
    S.entryOf.resize(ns);
    S.structural = ns;
    // Each kind band by band: its groups of eight evenly spaced springs, then its other springs.
    S.groupKernel = kes ? GroupKernel::None : groupKernelInUse();
    const bool groups = S.groupKernel != GroupKernel::None;
    const SpringOrder structuralOrder = groupSprings(cloth.springs, ns, cloth.particleCount(), groups);
    const SpringOrder bendOrder = groupSprings(merged.springs, nb, cloth.particleCount(), groups);
    S.groups = structuralOrder.groups;
    S.structuralGroups = S.groups.size();
    S.bands = structuralOrder.bands;
    S.structuralBands = S.bands.size();
    for (SpringGroup g : bendOrder.groups) {
        g.entry += uint32_t(ns);
        S.groups.push_back(g);
    }
    for (SpringBand b : bendOrder.bands) {
        b.groupsBegin += uint32_t(S.structuralGroups), b.groupsEnd += uint32_t(S.structuralGroups);
        b.restBegin += uint32_t(ns), b.restEnd += uint32_t(ns);
        S.bands.push_back(b);
    }
    const float kCap = kStiffnessCap / (dt * dt), kdCap = kDampingCap / dt;
    // An entry's springs: a structural entry's one, a bend-shear entry's merged copies.
    struct Copies {
        const Index* begin;
        const Index* end;
    };
    auto copiesOf = [&](size_t e) {
        if (e < ns) return Copies{&structuralOrder.order[e], &structuralOrder.order[e] + 1};
        const Index u = bendOrder.order[e - ns];
        return Copies{merged.copies.data() + merged.start[u], merged.copies.data() + merged.start[u + 1]};
    };
    // The stiffness and damping the material asks of each entry, summed over its copies in the order
    // fill sums the capped ones (so that an entry the guard left alone compares equal); fill writes
    // them as it goes, for the guard's figures below.
    UninitializedVector<float> askedK(ns + nb), askedKd(ns + nb);
    auto fill = [&](const std::vector<Spring>& springs, size_t e0, size_t e1, float ks, float kds) {
        for (size_t e = e0; e < e1; ++e) {
            const Copies c = copiesOf(e);
            const Spring& s = springs[*c.begin];
            float k = 0.f, damping = 0.f, kAsked = 0.f, kdAsked = 0.f;
            for (const Index* i = c.begin; i != c.end; ++i) {
                const Spring& copy = springs[*i];
                float kc = ks * copy.weight, dc = kds * copy.weight;
                kAsked += kc, kdAsked += dc;
                if (ctx.perSpringCaps) {
                    const float w = cloth.invMass[copy.a] + cloth.invMass[copy.b];
                    if (kc * w > kCap) kc = kCap / w;
                    if (dc * w > kdCap && !ctx.implicitDamping) dc = kdCap / w;
                }
                k += kc, damping += dc;
            }
            S.a16[e] = 16u * s.a;
            S.b16[e] = 16u * s.b;
            S.index[e] = *c.begin;
            if (e < ns) S.entryOf[*c.begin] = uint32_t(e);
            S.rest[e] = s.rest;
            S.k[e] = k;
            S.kd[e] = damping;
            askedK[e] = kAsked;
            askedKd[e] = kdAsked;
        }
    };
    fill(cloth.springs, 0, ns, float(stretchAsked.stiffness), float(stretchAsked.damping));
    fill(cloth.bends, ns, ns + nb, m.bendStiffness, m.bendDamping);
    if (guard) guardParticleBudget(cloth, S, dt, ctx.dragPerMass, ctx.implicitDamping);
    // The damping taken implicitly (integrate.cpp): each particle's summed damping, the
    // diagonal its Jacobi step divides by.
    S.implicitDamping = ctx.implicitDamping;
    S.dampingSum.clear();
    if (ctx.implicitDamping) {
        S.dampingSum.assign(cloth.particleCount(), 0.f);
        for (size_t e = 0; e < ns + nb; ++e) {
            S.dampingSum[S.a16[e] / 16] += S.kd[e];
            S.dampingSum[S.b16[e] / 16] += S.kd[e];
        }
    }
    // What the guard took from the material, for the report and the stats pane.
    size_t capped = 0;
    float stiffnessKept = 1.f, dampingKept = 1.f;
    if (guard)
        for (size_t e = 0; e < ns + nb; ++e) {
            const float wantK = askedK[e], wantKd = askedKd[e];
            // An entry the guard left as asked (fill computed the same sum) has a ratio of 1 or
            // more, which lowers neither minimum: no division for it (they were a chain of 100 k
            // divisions, a sixth of the rebuild after a tear at 128 x 128).
            const bool softer = S.k[e] < wantK, softerDamping = S.kd[e] < wantKd;
            if (!softer && !softerDamping) continue;
            if (S.k[e] < wantK * (1.f - 1e-6f) || S.kd[e] < wantKd * (1.f - 1e-6f)) {
                const Copies c = copiesOf(e);
                capped += size_t(c.end - c.begin);
            }
            if (softer && wantK > 0.f) stiffnessKept = std::min(stiffnessKept, S.k[e] / wantK);
            if (softerDamping && wantKd > 0.f) dampingKept = std::min(dampingKept, S.kd[e] / wantKd);
        }
    // The cloth's springs whose forces the groups compute (a merged entry stands for its copies).
    S.groupedSprings = 0;
    for (const SpringGroup& g : S.groups)
        for (size_t e = g.entry; e < g.entry + kGroupSize; ++e) {
            const Copies c = copiesOf(e);
            S.groupedSprings += size_t(c.end - c.begin);
        }
    S.mergedSprings = bends ? cloth.bends.size() - nb : 0;
    S.cappedSprings = capped;
    S.stiffnessKept = stiffnessKept;
    S.dampingKept = dampingKept;
    S.kes = kes;
    S.perSpringCaps = ctx.perSpringCaps;
    S.kesWidth.clear();
    if (kes) {
        S.kesWidth.resize(ns);
        for (size_t e = 0; e < ns; ++e) {
            const Spring& s = cloth.springs[S.index[e]];
            const float asked = float(stretchAsked.stiffness) * s.weight;
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
    // With the damping taken implicitly the integrator runs a second pass for it on the velocities
    // the other forces gave (integrate.cpp): this one leaves it out.
    springForcePass(ctx, cloth, state, S.implicitDamping ? SpringTerms::Elastic : SpringTerms::Both);
}

void springForcePass(const StepContext& ctx, Cloth& cloth, StepState& state, SpringTerms terms) {
    SpringCache& S = state.springs;
    const size_t n = cloth.particleCount();
    const size_t ns = S.structural, nb = S.a16.size() - S.structural;
    const int threads = int(state.threads.acc.size());
    const int nt = (threads > 1 && ns + nb >= kParallelWork) ? threads : 1;
    // Thread t's share of each kind: its chunk of the kind's entries, band by band its groups (a
    // group goes with its first entry) and its other springs.
    auto forShare = [&](int t, auto&& groups, auto&& rest) {
        for (int kind = 0; kind < 2; ++kind) {
            const size_t first = kind ? ns : 0;
            const Chunk c = chunkOf(kind ? nb : ns, t, nt);
            const size_t e0 = first + c.begin, e1 = first + c.end;
            const size_t b0 = kind ? S.structuralBands : 0, b1 = kind ? S.bands.size() : S.structuralBands;
            for (size_t b = b0; b < b1; ++b) {
                const SpringBand& band = S.bands[b];
                if (band.groupsEnd > band.groupsBegin) {
                    const size_t g0 = S.groups[band.groupsBegin].entry; // the band's first group entry
                    auto at = [&](size_t e) {
                        const size_t k = e <= g0 ? 0 : (e - g0 + kGroupSize - 1) / kGroupSize;
                        return std::min<size_t>(band.groupsBegin + k, band.groupsEnd);
                    };
                    if (at(e0) < at(e1)) groups(at(e0), at(e1));
                }
                const size_t r0 = std::max<size_t>(band.restBegin, e0), r1 = std::min<size_t>(band.restEnd, e1);
                if (r0 < r1) rest(r0, r1);
            }
        }
    };
    if (S.threadRange.size() != size_t(nt)) {
        S.threadRange.assign(nt, {n, 0});
        for (int t = 0; t < nt; ++t) {
            size_t lo = n, hi = 0;
            auto widen = [&](size_t b, size_t e) {
                for (size_t i = b; i < e; ++i) {
                    lo = std::min<size_t>(lo, std::min(S.a16[i], S.b16[i]) / 16);
                    hi = std::max<size_t>(hi, std::max(S.a16[i], S.b16[i]) / 16 + 1);
                }
            };
            forShare(
                t, [&](size_t g0, size_t g1) { widen(S.groups[g0].entry, S.groups[g1 - 1].entry + kGroupSize); }, widen);
            S.threadRange[t] = {lo, hi};
        }
    }
    for (int t = 0; t < nt; ++t) state.threads.range[t] = S.threadRange[t];
    const SpringArrays arrays = springArraysOf(S);
    const Vec3* x = cloth.x.data();
    const Vec3* v = cloth.v.data();
    PackedParticle* packed = state.packed.data();
    const bool grouped = !S.groups.empty();
    ctx.profile->groupedSprings = S.groupedSprings;
    ctx.profile->mergedSprings = S.mergedSprings;
    ctx.profile->springKernel = !grouped ? "generic" : S.groupKernel == GroupKernel::Avx2 ? "avx2" : "sse2";
    float* components[6] = {};
    if (grouped) {
        state.components.resize(n, 6);
        for (int c = 0; c < 6; ++c) components[c] = state.components.component(c);
        // One per force buffer, not per thread this phase uses: the wind phase may fill a buffer
        // this one did not, and the integrator reads a group array beside every buffer it reads.
        state.threads.groupForces.resize(size_t(threads));
        for (ComponentArrays& f : state.threads.groupForces) f.resize(n, 3);
    }
    state.threads.groupForcesSet = grouped;
    // The damping pass (integrate.cpp) runs on the positions the elastic pass packed and on the
    // velocities the integrator's first stage wrote into the packed copy (nothing moves a particle
    // between them): only the groups' velocity components are copied anew.
    const bool dampingPass = terms == SpringTerms::Damping;
    parallelRegion(ns + nb, nt, [&](int t, int nt2) {
        const Chunk pc = chunkOf(n, t, nt2);
        if (!dampingPass) packParticles(pc.begin, pc.end, n, x, v, packed, grouped ? components : nullptr);
        else if (grouped) packVelocities(pc.begin, pc.end, packed, components + 3);
        parallelBarrier(nt2);
        Eigen::Vector4f* acc = state.threads.acc[t].data();
        forShare(
            t,
            [&](size_t g0, size_t g1) {
                springForcesGrouped(S.groupKernel, terms, S.groups.data(), g0, g1, S.rest.data(), S.k.data(),
                                    S.kd.data(), state.components, state.threads.groupForces[size_t(t)]);
            },
            [&](size_t e0, size_t e1) {
                switch (terms) {
                case SpringTerms::Both: springForces<SpringTerms::Both>(arrays, e0, e1, packed, acc); break;
                case SpringTerms::Elastic: springForces<SpringTerms::Elastic>(arrays, e0, e1, packed, acc); break;
                case SpringTerms::Damping: springForces<SpringTerms::Damping>(arrays, e0, e1, packed, acc); break;
                }
            });
    });
}

} // namespace clothtear
