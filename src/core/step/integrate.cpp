// The explicit integrators (semi-implicit Euler, forward Euler, Verlet) over the particles, summing
// the per-thread force buffers; and the kinematic drivers.
#include "parallel.h"
#include "phases.h"

#include <algorithm>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace clothtear {

void moveDrivers(const StepContext& ctx, Cloth& cloth, StepState& state) {
    for (const Driver& d : *ctx.drivers)
        for (Index p : d.particles) {
            cloth.x[p] += d.velocity * ctx.dt;
            cloth.v[p] = d.velocity;
            if (p < state.packed.size()) // the strain scan and the tethers read these
                state.packed[p] = packedOf(cloth.x[p], cloth.v[p]);
        }
}

namespace {

struct IntegrateParams {
    Vec3 g;            // m/s^2
    float dragPerMass; // 1/s
    float keep;        // Keserica: velocity kept per step
    float verletKeep;  // Verlet: 1 - friction
    bool verletStart;  // Verlet: first step since a rebuild or a change of integrator
    Vec3* verletKick;  // Verlet: per particle, half the last step's velocity change (a dt / 2)
    float dt;
    const float* dampingSum; // implicit damping: per particle, its springs' summed kd (SpringCache)
};

// What integrateRange does with the forces it sums. Whole: the integrator's step. With the damping
// taken implicitly (semi-implicit Euler only), two stages around a second spring pass:
//   Velocity  v* = v + a dt from every force but the springs' damping; x stays
//   Damping   the forces summed are the damping's at v* (f_d = -K_d v*, K_d its Laplacian-like
//             matrix); one Jacobi step of (M / dt + K_d) v = (M / dt) v* from v*:
//               v = v* + f_d / (m / dt + c),  c = the particle's summed kd >= its block of K_d,
//             then x += v dt. Since K_d <= 2 diag(c) and m / dt > 0, the step's matrix
//             I - (M / dt + c)^-1 K_d has its eigenvalues in (-1, 1]: stable at any dt, and v* is
//             left as it is where the cloth moves as a whole (f_d = 0). As dt -> 0 it is the
//             explicit damping. Applied after the other forces, a mode's elastic bound stays
//             (omega dt)^2 < 4 however strong its damping (bench/README.md, "The springs' damping
//             and the guard's step").
enum class Stage { Whole, Velocity, Damping };

// (x, y, z, 0). Eigen's constructor from four scalars went through the stack here, and the 16-byte
// load of what three smaller stores had just written could not be forwarded (the integrator at 8 x
// its cost).
inline Eigen::Vector4f vector4(float x, float y, float z) {
#if defined(__SSE2__)
    Eigen::Vector4f r;
    _mm_store_ps(r.data(), _mm_setr_ps(x, y, z, 0.f));
    return r;
#else
    return Eigen::Vector4f(x, y, z, 0.f);
#endif
}

// Particles [b, e), whose forces are in the NB buffers `buf` (NB < 0: nb of them) and, with G, in
// the spring groups' arrays of the same threads (`groups`: x, y, z, `stride` floats apart;
// spring_groups.h): sums and clears those entries, then integrates. The
// packed copy holds x and v as phaseSprings read them (nothing moves a particle in between) and gets
// the new ones (the strain scan and the tethers read them).
template <Integrator I, Stage St, int NB, bool G>
void integrateRange(size_t b, size_t e, Eigen::Vector4f* const* buf, float* const* groups, size_t stride, int nb,
                    const IntegrateParams& P, Vec3* x, Vec3* v, PackedParticle* packed, const float* invMass) {
    using V4 = Eigen::Vector4f;
    const V4 g(P.g.x(), P.g.y(), P.g.z(), 0.f);
    const int count = NB >= 0 ? NB : nb;
    for (size_t p = b; p < e; ++p) {
        V4 f = V4::Zero();
        for (int k = 0; k < count; ++k) {
            f += buf[k][p];
            buf[k][p].setZero();
            if constexpr (G) {
                float* g = groups[k] + p;
                f += vector4(g[0], g[stride], g[2 * stride]);
                g[0] = g[stride] = g[2 * stride] = 0.f;
            }
        }
        const float w = invMass[p];
        if (w == 0.f) continue;
        Eigen::Map<V4, Eigen::Aligned16> px(packed[p].x), pv(packed[p].v);
        V4 xn = px, vn = pv;
        if constexpr (St == Stage::Damping) {
            vn += f * (P.dt * w / (1.f + P.dt * w * P.dampingSum[p]));
            xn += vn * P.dt;
            px = xn;
            pv = vn;
            x[p] = xn.head<3>();
            v[p] = vn.head<3>();
            continue;
        }
        const V4 a = g - P.dragPerMass * vn + f * w;
        if constexpr (St == Stage::Velocity) {
            // v* goes to the packed copy only: the damping pass reads it there, and the damping
            // stage writes v.
            vn = (vn + a * P.dt) * P.keep;
            pv = vn;
            continue;
        }
        if constexpr (I == Integrator::SemiImplicitEuler) {
            vn = (vn + a * P.dt) * P.keep;
            xn += vn * P.dt;
        } else if constexpr (I == Integrator::ForwardEuler) {
            xn += vn * P.dt;
            vn = (vn + a * P.dt) * P.keep;
        } else {
            // Velocity form, second order. The state is u = (x_n - x_{n-1}) / dt as computed (not
            // recomputed from rounded positions) plus the half kick a_{n-1} dt / 2, so that v = u +
            // kick is the velocity at t_n to second order (the springs' damping and the air read
            // it; with u alone they made the method first order). Position form in float quantizes
            // u to ulp(x) / dt each step and drops a dt^2 below half an ulp: at dt = 1/3840 s its
            // error grew as dt^-2 (bench/README.md). Every phase that moves x moves v with it
            // (limit, tethers: v += delta / dt; collisions and impulses already did). The first
            // step (P.verletStart) takes kick = a dt / 2: the Taylor step x + v dt + a dt^2 / 2.
            const Vec3& k = P.verletKick[p];
            const V4 kickPrev = P.verletStart ? V4(a * (0.5f * P.dt)) : V4(k.x(), k.y(), k.z(), 0.f);
            const V4 step = (P.verletKeep * P.keep * P.dt) * (vn - kickPrev) + a * (P.dt * P.dt);
            const V4 kick = a * (0.5f * P.dt);
            P.verletKick[p] = kick.head<3>();
            vn = step * (1.f / P.dt) + kick;
            xn += step;
        }
        px = xn;
        pv = vn;
        x[p] = xn.head<3>();
        v[p] = vn.head<3>();
    }
}

// One chunk of particles, split where the set of force buffers that cover it changes.
template <Integrator I, Stage St = Stage::Whole>
void integrateKernel(Chunk c, const IntegrateParams& P, Vec3* x, Vec3* v, PackedParticle* packed,
                         const float* invMass, ThreadBuffers& T) {
    auto& acc = T.acc;
    const auto* ranges = T.range.data();
    const bool G = T.groupForcesSet;
    const size_t stride = G ? T.groupForces[0].stride : 0;
    std::vector<size_t> cuts{c.begin, c.end};
    for (size_t k = 0; k < acc.size(); ++k)
        for (size_t edge : ranges[k])
            if (edge > c.begin && edge < c.end) cuts.push_back(edge);
    std::sort(cuts.begin(), cuts.end());
    for (size_t s = 0; s + 1 < cuts.size(); ++s) {
        const size_t b = cuts[s], e = cuts[s + 1];
        if (b == e) continue;
        Eigen::Vector4f* buf[kMaxThreadSlots];
        float* groups[kMaxThreadSlots];
        int nb = 0;
        for (size_t k = 0; k < acc.size(); ++k)
            if (ranges[k][0] <= b && ranges[k][1] >= e) {
                groups[nb] = G ? T.groupForces[k].data.data() : nullptr;
                buf[nb++] = acc[k].data();
            }
        auto run = [&]<int NB, bool WithGroups>() {
            integrateRange<I, St, NB, WithGroups>(b, e, buf, groups, stride, nb, P, x, v, packed, invMass);
        };
        switch (nb * 2 + G) {
        case 0: case 1: run.template operator()<0, false>(); break;
        case 2: run.template operator()<1, false>(); break;
        case 3: run.template operator()<1, true>(); break;
        case 4: run.template operator()<2, false>(); break;
        case 5: run.template operator()<2, true>(); break;
        default: G ? run.template operator()<-1, true>() : run.template operator()<-1, false>(); break;
        }
    }
}

} // namespace

// a = external acceleration (gravity, air drag) + (sum of spring and wind forces) / m.
//   semi-implicit Euler (Onal 2.1):  v += a dt;  x += v dt
//   forward Euler:                   x += v dt;  v += a dt
//   Verlet (Keserica 2.2.1):         x' = x + (1 - f)(x - x_prev) + a dt^2;  v = (x' - x) / dt + a dt / 2
//                                    (first step: x' = x + v dt + a dt^2 / 2; see integrateRange)
// Pinned particles (invMass 0) do not move here; drivers move theirs kinematically.
void phaseIntegrate(const StepContext& ctx, Cloth& cloth, StepState& state) {
    const size_t n = cloth.particleCount();
    const int threads = int(state.threads.acc.size());
    const bool verlet = ctx.integrator == Integrator::Verlet;
    IntegrateParams P;
    P.g = ctx.gravity;
    P.dragPerMass = ctx.dragPerMass;
    P.keep = ctx.keep;
    P.verletKeep = 1.f - ctx.settings->time.verletFriction;
    P.verletStart = verlet && !state.verletRunning;
    state.verletRunning = verlet;
    if (verlet) state.verletKick.resize(n, Vec3::Zero()); // torn-off copies start at 0
    P.verletKick = state.verletKick.data();
    P.dt = ctx.dt;
    P.dampingSum = state.springs.dampingSum.data();
    Vec3* x = cloth.x.data();
    Vec3* v = cloth.v.data();
    const float* invMass = cloth.invMass.data();
    PackedParticle* packed = state.packed.data();
    ThreadBuffers& T = state.threads;
    if (ctx.implicitDamping) {
        // Semi-implicit Euler only (implicitDampingAllowed); the springs phase left the damping out.
        auto stage = [&]<Stage St>() {
            parallelRegion(n, threads, [&](int t, int nt) {
                integrateKernel<Integrator::SemiImplicitEuler, St>(chunkOf(n, t, nt), P, x, v, packed, invMass, T);
            });
        };
        stage.template operator()<Stage::Velocity>();
        springForcePass(ctx, cloth, state, SpringTerms::Damping); // the damping at v*
        stage.template operator()<Stage::Damping>();
        T.groupForcesSet = false;
        moveDrivers(ctx, cloth, state);
        return;
    }
    parallelRegion(n, threads, [&](int t, int nt) {
        const Chunk c = chunkOf(n, t, nt);
        switch (ctx.integrator) {
        case Integrator::SemiImplicitEuler:
            integrateKernel<Integrator::SemiImplicitEuler>(c, P, x, v, packed, invMass, T);
            break;
        case Integrator::ForwardEuler:
            integrateKernel<Integrator::ForwardEuler>(c, P, x, v, packed, invMass, T);
            break;
        case Integrator::Verlet:
            integrateKernel<Integrator::Verlet>(c, P, x, v, packed, invMass, T);
            break;
        default: break; // the references go through phaseIntegrateReference
        }
    });
    T.groupForcesSet = false;
    moveDrivers(ctx, cloth, state);
}

} // namespace clothtear
