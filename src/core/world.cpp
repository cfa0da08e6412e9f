// The step: named, timed phases over flat arrays. See world.h for the phase list.
//
// Section index:
//   [SETUP]      rebuild, pinning, settings
//   [STEP]       step / substep and the phase driver
//   [FORCES]     force buffers, spring cache, spring forces (kernels: step_kernels.h), wind
//   [INTEGRATE]  gravity, air friction; semi-implicit Euler, forward Euler, Verlet; the references
//                (implicit Euler, XPBD: implicit_euler.h, xpbd.h) with their springs
//   [LIMIT]      strain scan, tethers (tethers.h), Provot length limiting (averaged Jacobi)
//   [MISC]       impulse, energy, bookkeeping
#include "clothtear/world.h"

#include "clothtear/tear.h"
#include "collide.h"
#include "finite_check.h"
#include "implicit_euler.h"
#include "parallel.h"
#include "step_kernels.h"
#include "tethers.h"
#include "xpbd.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>

namespace clothtear {

const char* phaseName(Phase p) {
    static const char* names[] = {"forces",  "springs", "wind", "integrate",  "collide",
                                  "limit", "contact", "tear", "bookkeeping"};
    return names[int(p)];
}

namespace {

// Times one phase into the profile; the scope reads like the algorithm in substep().
class PhaseTimer {
public:
    PhaseTimer(StepProfile& profile, Phase phase) : profile_(profile), phase_(phase), start_(Clock::now()) {}
    ~PhaseTimer() {
        profile_.ms[int(phase_)] += std::chrono::duration<double, std::milli>(Clock::now() - start_).count();
        profile_.runs[int(phase_)]++;
    }

private:
    using Clock = std::chrono::steady_clock;
    StepProfile& profile_;
    Phase phase_;
    Clock::time_point start_;
};

// A 64-bit mix of an integer (splitmix64). Summed over the pinned particles it is an
// order-independent signature of the set; chained, a key for the caches of the step.
inline uint64_t hashIndex(uint64_t p) {
    p = (p + 0x9e3779b97f4a7c15ull) * 0xbf58476d1ce4e5b9ull;
    return (p ^ (p >> 31)) * 0x94d049bb133111ebull;
}
inline uint32_t bitsOf(float f) {
    uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    return u;
}

// Debug builds check for NaN/Inf at every phase boundary whatever check.finite says.
#if CLOTHTEAR_CHECK_FINITE
constexpr bool kAlwaysCheckFinite = true;
#else
constexpr bool kAlwaysCheckFinite = false;
#endif

// Threads worth using for a cloth of n particles (forking costs a few microseconds).
int threadsFor(size_t particles) { return particles >= 2048 ? std::min(maxThreads(), kMaxThreadSlots) : 1; }

} // namespace

// ============================================================================================ [SETUP]

std::string World::rebuild() {
    const ClothSettings& c = settings.cloth;
    if (c.mesh == MeshType::Obj) return rebuild(restMesh);
    MeshData mesh = c.mesh == MeshType::Grid
                        ? makeGridMesh(c.resolutionX, c.resolutionY, c.width, c.height)
                        : makeIrregularMesh(c.resolutionX, c.resolutionY, c.width, c.height, c.jitter, uint32_t(c.seed));
    return rebuild(mesh);
}

std::string World::rebuild(const MeshData& mesh) {
    Result<Cloth> built = buildCloth(mesh, settings.material.density);
    if (!built.ok()) return built.error;
    if (&mesh != &restMesh) restMesh = mesh;
    cloth = std::move(built.value);
    scratch_ = StepScratch{}; // the caches of the step belong to the old cloth
    // Tilt about the top edge: 0 deg hangs in the x-y plane, 90 deg lies horizontal towards +z.
    if (settings.cloth.tilt != 0.f) {
        float top = -1e30f;
        for (const Vec3& x : cloth.x) top = std::max(top, x.y());
        const float a = settings.cloth.tilt * float(M_PI / 180.0);
        for (Vec3& x : cloth.x) {
            const float dy = x.y() - top;
            x = Vec3(x.x(), top + dy * std::cos(a), x.z() - dy * std::sin(a));
        }
        cloth.xPrev = cloth.x;
    }
    balls.clear();
    drivers.clear();
    tearLog = TearLog{};
    profile.reset();
    time = 0;
    steps = 0;
    maxStrain = 0;
    wake();
    sleptFrames = 0;
    finite = true;
    nonFiniteWhere.clear();
    pinByMode(settings.cloth.pin);
    return {};
}

void World::applySettings() {
    if (cloth.density != settings.material.density) cloth.setDensity(settings.material.density);
}

void World::pinByMode(PinMode mode) {
    const size_t n = cloth.particleCount();
    for (Index p = 0; p < n; ++p) cloth.setPinned(p, false);
    if (mode == PinMode::None || n == 0) return;
    double top = -1e300, left = 1e300, right = -1e300;
    for (const Vec3d& r : cloth.rest) {
        top = std::max(top, r.y());
        left = std::min(left, r.x());
        right = std::max(right, r.x());
    }
    const double eps = 1e-6 * std::max(1.0, right - left);
    if (mode == PinMode::TopEdge) {
        for (Index p = 0; p < n; ++p)
            if (cloth.rest[p].y() > top - eps) cloth.setPinned(p, true);
    } else if (mode == PinMode::LeftEdge) {
        for (Index p = 0; p < n; ++p)
            if (cloth.rest[p].x() < left + eps) cloth.setPinned(p, true);
    } else if (mode == PinMode::LeftRightEdges) {
        for (Index p = 0; p < n; ++p)
            if (cloth.rest[p].x() < left + eps || cloth.rest[p].x() > right - eps) cloth.setPinned(p, true);
    } else if (mode == PinMode::TopCorners) {
        // The particles closest to the two top corners.
        Index best[2] = {0, 0};
        double bestD[2] = {1e300, 1e300};
        for (Index p = 0; p < n; ++p) {
            const double dl = (cloth.rest[p] - Vec3d(left, top, cloth.rest[p].z())).squaredNorm();
            const double dr = (cloth.rest[p] - Vec3d(right, top, cloth.rest[p].z())).squaredNorm();
            if (dl < bestD[0]) bestD[0] = dl, best[0] = p;
            if (dr < bestD[1]) bestD[1] = dr, best[1] = p;
        }
        cloth.setPinned(best[0], true);
        cloth.setPinned(best[1], true);
    }
}

// ============================================================================================= [STEP]

void World::step() {
    applySettings();
    if (stayAsleep()) {
        time += settings.time.frameDt;
        ++steps;
        ++sleptFrames;
        return;
    }
    if (settings.sleep.enabled) scratch_.frameStart = cloth.x;
    frameSubsteps = guardSubsteps();
    substepsNow_ = frameSubsteps;
    for (int i = 0; i < frameSubsteps; ++i) substep();
    substepsNow_ = 0;
    phaseBookkeeping();
    ++steps;
    updateSleep();
}

// The stability guard, first part: with an explicit integrator, take enough sub-steps that the
// material as set is stable (stability.cpp), up to time.max_substeps. Whatever is still too stiff
// at that step is capped spring by spring in the spring cache (phaseSprings), so the guard never
// lets a frame explode, and where the budget allows, the cloth keeps its stiffness.
int World::guardSubsteps() {
    const TimeSettings& T = settings.time;
    if (!T.stabilityGuard || !isExplicit(T.integrator) || T.maxSubsteps <= T.substeps) return T.substeps;
    const MaterialSettings& m = settings.material;
    uint64_t key = hashIndex(cloth.topologyRevision) ^ hashIndex(scratch_.pinSignature + 3);
    for (uint64_t word : {uint64_t(cloth.particleCount()), uint64_t(cloth.springs.size()), uint64_t(cloth.bends.size()),
                          uint64_t(bitsOf(m.stretchStiffness)), uint64_t(bitsOf(m.stretchDamping)),
                          uint64_t(bitsOf(m.bendStiffness)), uint64_t(bitsOf(m.bendDamping)),
                          uint64_t(bitsOf(cloth.density)), uint64_t(T.integrator)})
        key = hashIndex(key ^ word);
    if (key != guardKey_) {
        guardStep_ = stableStepEstimate(cloth, settings);
        guardKey_ = key;
    }
    const double need = std::ceil(double(T.frameDt) / guardStep_);
    return need > double(T.maxSubsteps) ? T.maxSubsteps : std::max(T.substeps, int(need));
}

void World::substep() {
    const int substeps = substepsNow_ > 0 ? substepsNow_ : settings.time.substeps;
    const float dt = settings.time.frameDt / float(substeps);
    // The reference integrators treat the springs inside their own step.
    const bool reference = !isExplicit(settings.time.integrator);
    // Debug builds and check.finite: the first phase boundary with a NaN/Inf is reported
    // (nonFiniteWhere). A check after a phase that did not run finds what the previous one found.
    const bool check = kAlwaysCheckFinite || settings.check.finite;
    if (check) checkFinite(-1);
    {
        PhaseTimer t(profile, Phase::Forces);
        phaseForces(dt);
    }
    if (!reference) {
        PhaseTimer t(profile, Phase::Springs);
        phaseSprings(dt);
    }
    if (check) checkFinite(int(Phase::Springs));
    if (settings.wind.enabled && settings.wind.speed > 0.f && settings.wind.dragCoefficient > 0.f) {
        PhaseTimer t(profile, Phase::Wind);
        phaseWind(dt);
    }
    if (check) checkFinite(int(Phase::Wind));
    {
        PhaseTimer t(profile, Phase::Integrate);
        if (reference) phaseIntegrateReference(dt);
        else phaseIntegrate(dt);
    }
    if (check) checkFinite(int(Phase::Integrate));
    if (!balls.empty()) {
        PhaseTimer t(profile, Phase::Collide);
        phaseCollide(dt);
    }
    if (check) checkFinite(int(Phase::Collide));
    // The limit pass doubles as the strain scan, so it runs when either needs it.
    if ((settings.limit.enabled && settings.limit.iterations > 0) || settings.tear.enabled) {
        PhaseTimer t(profile, Phase::Limit);
        phaseLimit(dt);
    }
    if (check) checkFinite(int(Phase::Limit));
    if (!balls.empty() || settings.collision.ground) {
        PhaseTimer t(profile, Phase::Contact);
        phaseContact(dt);
    }
    if (check) checkFinite(int(Phase::Contact));
    if (settings.tear.enabled && !scratch_.tearCandidates.empty()) {
        PhaseTimer t(profile, Phase::Tear);
        phaseTear();
    }
    if (check) checkFinite(int(Phase::Tear));
    time += dt;
    profile.substeps++;
}

// =========================================================================================== [FORCES]

// Gravity and air friction are applied in the integrator, per particle, where the velocity is read
// anyway (a = g - (c / density) v: physical drag F = -c A v with A the particle's area share, the
// same acceleration at any resolution; Keserica's "10% per step" model is a factor there too).
// This phase only sizes the per-thread force buffers. They are zero between sub-steps: the
// integrator clears every entry it reads, so nothing here touches all particles.
void World::phaseForces(float /*dt*/) {
    const size_t n = cloth.particleCount();
    const size_t threads = size_t(threadsFor(n));
    auto& acc = scratch_.threadAcc;
    if (acc.size() != threads) acc.resize(threads);
    for (auto& buffer : acc)
        if (buffer.size() != n) buffer.resize(n, Eigen::Vector4f::Zero());
    scratch_.threadRange.assign(threads, {n, 0});
    scratch_.packed.resize(n);
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
void World::refreshSpringCache(float dt) {
    SpringCache& S = scratch_.springs;
    const MaterialSettings& m = settings.material;
    const bool bends = m.bendStiffness > 0.f || m.bendDamping > 0.f;
    const bool guard = settings.time.stabilityGuard;
    uint64_t key = hashIndex(cloth.topologyRevision) ^ hashIndex(scratch_.pinSignature + 1);
    for (uint64_t word : {uint64_t(uintptr_t(cloth.springs.data())), uint64_t(cloth.springs.size()),
                          uint64_t(uintptr_t(cloth.bends.data())), uint64_t(cloth.bends.size()),
                          uint64_t(bitsOf(m.stretchStiffness)), uint64_t(bitsOf(m.stretchDamping)),
                          uint64_t(bitsOf(m.bendStiffness)), uint64_t(bitsOf(m.bendDamping)), uint64_t(bitsOf(dt)),
                          uint64_t(bitsOf(cloth.density)), uint64_t(guard) + 2 * uint64_t(bends),
                          uint64_t(bitsOf(guardDragPerMass(dt))), cloth.massRevision})
        key = hashIndex(key ^ word);
    if (key == S.key) return;
    const size_t ns = cloth.springs.size(), nb = bends ? cloth.bends.size() : 0;
    for (auto* a : {&S.a16, &S.b16}) a->resize(ns + nb);
    S.index.resize(ns + nb);
    for (auto* a : {&S.rest, &S.k, &S.kd}) a->resize(ns + nb);
    S.structural = ns;
    const float kCap = 1.f / (3.f * dt * dt), kdCap = 1.f / (6.f * dt);
    auto fill = [&](const std::vector<Spring>& springs, size_t count, size_t offset, float ks, float kds) {
        constexpr size_t kBlock = 64, kWays = 8, kLane = kBlock / kWays;
        for (size_t e = 0; e < count; ++e) {
            // Entry e of this kind takes spring i (a permutation within full blocks).
            const size_t base = e - e % kBlock, q = e % kBlock;
            const size_t i = base + kBlock <= count ? base + (q % kWays) * kLane + q / kWays : e;
            const Spring& s = springs[i];
            float k = ks * s.weight, damping = kds * s.weight;
            if (guard) {
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
    fill(cloth.springs, ns, 0, m.stretchStiffness, m.stretchDamping);
    fill(cloth.bends, nb, ns, m.bendStiffness, m.bendDamping);
    if (guard) guardParticleBudget(dt, guardDragPerMass(dt));
    S.maxRest = 0.f;
    for (size_t e = 0; e < ns; ++e) S.maxRest = std::max(S.maxRest, S.rest[e]);
    S.threadRange.clear(); // recomputed for the thread count in use
    S.key = key;
}

// Air drag as the integrator applies it: with the guard on, capped at 0.5 / dt (explicit drag
// v -= c/rho v dt overshoots past zero velocity beyond 1 / dt and explodes beyond 2 / dt; a light
// cloth in the safe ranges reaches c/rho = 500 1/s).
float World::guardDragPerMass(float dt) const {
    const float c = settings.air.model == AirModel::Drag ? settings.air.dragCoefficient / cloth.density : 0.f;
    return settings.time.stabilityGuard ? std::min(c, 0.5f / dt) : c;
}

// Stability guard, per particle. The caps of refreshSpringCache bound each spring alone; a particle
// with many capped springs (a sliver mesh, a fan of torn triangles, strong damping) can still add
// up past the stable region. Gershgorin (stability.cpp): semi-implicit Euler is stable while, for
// every particle p,
//   dt^2 w_p sum(k) / 2 + dt w_p sum(kd) + dt c_air < 1.
// Where a particle's springs add up past kParticleBudget, they are scaled down by the factor that
// brings it back (a spring takes the smaller factor of its two ends, so both ends end within the
// budget). At the defaults the per-spring caps already keep every particle inside, so this changes
// nothing there; it is what keeps random safe parameter sets finite (tests/test_stability.cpp).
void World::guardParticleBudget(float dt, float dragPerMass) {
    constexpr float kParticleBudget = 0.9f;
    SpringCache& S = scratch_.springs;
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
void World::phaseSprings(float dt) {
    refreshSpringCache(dt);
    SpringCache& S = scratch_.springs;
    const size_t n = cloth.particleCount();
    const size_t ns = S.structural, nb = S.a16.size() - S.structural;
    const int threads = int(scratch_.threadAcc.size());
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
    for (int t = 0; t < nt; ++t) scratch_.threadRange[t] = S.threadRange[t];
    const SpringArrays arrays{S.a16.data(), S.b16.data(), S.rest.data(), S.k.data(), S.kd.data()};
    const Vec3* x = cloth.x.data();
    const Vec3* v = cloth.v.data();
    PackedParticle* packed = scratch_.packed.data();
    parallelRegion(ns + nb, nt, [&](int t, int nt2) {
        const Chunk pc = chunkOf(n, t, nt2);
        for (size_t p = pc.begin; p < pc.end; ++p) {
            PackedParticle& q = packed[p];
            q = PackedParticle{{x[p].x(), x[p].y(), x[p].z(), 0.f}, {v[p].x(), v[p].y(), v[p].z(), 0.f}};
        }
        parallelBarrier(nt2);
        Eigen::Vector4f* acc = scratch_.threadAcc[t].data();
        const auto c = chunks(t);
        springForces(arrays, c[0].begin, c[0].end, packed, acc);
        springForces(arrays, ns + c[1].begin, ns + c[1].end, packed, acc);
    });
}

// Wind on each triangle from its normal and the relative air velocity (so a flag flutters):
//   F = c A (n . v_rel) |n . v_rel| n,   v_rel = wind - mean triangle velocity, shared by the corners,
//   A = current area, at most twice the rest area.
//
// With the stability guard on, the force on a triangle is capped so that it cannot change its
// lightest corner's normal velocity by more than the relative normal speed in one sub-step (drag
// can bring the cloth to the air's speed, not past it): explicit quadratic drag on a light cloth
// in a strong wind (rho = 0.01 kg/m^2, 30 m/s, both in the safe ranges) overshoots and explodes.
void World::phaseWind(float dt) {
    const WindSettings& w = settings.wind;
    Vec3 dir(w.dirX, w.dirY, w.dirZ);
    if (dir.squaredNorm() < 1e-12f) return;
    dir.normalize();
    // Gusts: two incommensurate sines, deterministic in time.
    const double ph = 2.0 * M_PI * w.gustFrequency * time;
    const float gustFactor = 1.f + w.gust * float(0.65 * std::sin(ph) + 0.35 * std::sin(2.37 * ph + 1.3));
    const Vec3 wind = dir * (w.speed * std::max(0.f, gustFactor));
    const Vec3* x = cloth.x.data();
    const Vec3* v = cloth.v.data();
    const float* invMass = cloth.invMass.data();
    const bool guard = settings.time.stabilityGuard;
    const int threads = int(scratch_.threadAcc.size());
    for (auto& r : scratch_.threadRange) r = {0, cloth.particleCount()}; // wind may touch any particle
    parallelRegion(cloth.triangles.size(), threads, [&](int t, int nt) {
        Eigen::Vector4f* acc = scratch_.threadAcc[t].data();
        const Chunk c = chunkOf(cloth.triangles.size(), t, nt);
        for (size_t i = c.begin; i < c.end; ++i) {
            const Triangle& tri = cloth.triangles[i];
            const Vec3 cross = (x[tri.p[1]] - x[tri.p[0]]).cross(x[tri.p[2]] - x[tri.p[0]]);
            const float twiceArea = cross.norm();
            if (!(twiceArea > 0.f)) continue;
            const Vec3 nrm = cross / twiceArea;
            const Vec3 vrel = wind - (v[tri.p[0]] + v[tri.p[1]] + v[tri.p[2]]) * (1.f / 3.f);
            const float vn = nrm.dot(vrel);
            // The corners' masses come from the rest area: a sliver torn to 1e-15 m^2 whose float
            // corners cannot get closer than ~1e-8 m would catch 10^4 times its share of wind and
            // explode (soak; also with the guard off). Its area counts up to twice the rest area.
            const float area = std::min(0.5f * twiceArea, 2.f * float(tri.restArea));
            float mag = w.dragCoefficient * area * vn * std::abs(vn) / 3.f;
            if (guard) {
                const float wMax = std::max({invMass[tri.p[0]], invMass[tri.p[1]], invMass[tri.p[2]]});
                const float cap = std::abs(vn) / (dt * std::max(wMax, 1e-30f));
                mag = std::clamp(mag, -cap, cap);
            }
            const Vec3 f = mag * nrm;
            for (Index p : tri.p) acc[p].head<3>() += f;
        }
    });
}

// ======================================================================================== [INTEGRATE]

void World::moveDrivers(float dt) {
    for (const Driver& d : drivers)
        for (Index p : d.particles) {
            cloth.xPrev[p] = cloth.x[p];
            cloth.x[p] += d.velocity * dt;
            cloth.v[p] = d.velocity;
            if (p < scratch_.packed.size())
                for (int k = 0; k < 3; ++k) { // the strain scan and the tethers read these
                    scratch_.packed[p].x[k] = cloth.x[p][k];
                    scratch_.packed[p].v[k] = cloth.v[p][k];
                }
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
};

// Particles [b, e), whose forces are in the NB buffers `buf` (NB < 0: nb of them): sums and clears
// those entries, then integrates. The packed copy holds x and v as phaseSprings read them (nothing
// moves a particle in between) and gets the new ones (the strain scan and the tethers read them).
// Adds the hash of each pinned particle met to `pinned`.
template <Integrator I, int NB>
void integrateRange(size_t b, size_t e, Eigen::Vector4f* const* buf, int nb, const IntegrateParams& P, Vec3* x,
                    Vec3* v, Vec3* xPrev, PackedParticle* packed, const float* invMass, uint64_t& pinned) {
    using V4 = Eigen::Vector4f;
    const V4 g(P.g.x(), P.g.y(), P.g.z(), 0.f);
    const int count = NB >= 0 ? NB : nb;
    for (size_t p = b; p < e; ++p) {
        V4 f = V4::Zero();
        for (int k = 0; k < count; ++k) {
            f += buf[k][p];
            buf[k][p].setZero();
        }
        const float w = invMass[p];
        if (w == 0.f) {
            pinned += hashIndex(p);
            continue;
        }
        Eigen::Map<V4, Eigen::Aligned16> px(packed[p].x), pv(packed[p].v);
        V4 xn = px, vn = pv;
        const V4 a = g - P.dragPerMass * vn + f * w;
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
            xPrev[p] = xn.head<3>();
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
template <Integrator I>
uint64_t integrateKernel(Chunk c, const IntegrateParams& P, Vec3* x, Vec3* v, Vec3* xPrev, PackedParticle* packed,
                         const float* invMass, std::vector<std::vector<Eigen::Vector4f>>& acc,
                         const std::array<size_t, 2>* ranges) {
    uint64_t pinned = 0;
    std::vector<size_t> cuts{c.begin, c.end};
    for (size_t k = 0; k < acc.size(); ++k)
        for (size_t edge : ranges[k])
            if (edge > c.begin && edge < c.end) cuts.push_back(edge);
    std::sort(cuts.begin(), cuts.end());
    for (size_t s = 0; s + 1 < cuts.size(); ++s) {
        const size_t b = cuts[s], e = cuts[s + 1];
        if (b == e) continue;
        Eigen::Vector4f* buf[kMaxThreadSlots];
        int nb = 0;
        for (size_t k = 0; k < acc.size(); ++k)
            if (ranges[k][0] <= b && ranges[k][1] >= e) buf[nb++] = acc[k].data();
        switch (nb) {
        case 0: integrateRange<I, 0>(b, e, buf, nb, P, x, v, xPrev, packed, invMass, pinned); break;
        case 1: integrateRange<I, 1>(b, e, buf, nb, P, x, v, xPrev, packed, invMass, pinned); break;
        case 2: integrateRange<I, 2>(b, e, buf, nb, P, x, v, xPrev, packed, invMass, pinned); break;
        default: integrateRange<I, -1>(b, e, buf, nb, P, x, v, xPrev, packed, invMass, pinned); break;
        }
    }
    return pinned;
}

} // namespace

// a = external acceleration (gravity, air drag) + (sum of spring and wind forces) / m.
//   semi-implicit Euler (Onal 2.1):  v += a dt;  x += v dt
//   forward Euler:                   x += v dt;  v += a dt
//   Verlet (Keserica 2.2.1):         x' = x + (1 - f)(x - x_prev) + a dt^2;  v = (x' - x) / dt + a dt / 2
//                                    (first step: x' = x + v dt + a dt^2 / 2; see integrateRange)
// Pinned particles (invMass 0) do not move here; drivers move theirs kinematically.
void World::phaseIntegrate(float dt) {
    const size_t n = cloth.particleCount();
    const int threads = int(scratch_.threadAcc.size());
    IntegrateParams P;
    P.g = Vec3(settings.gravity.x, settings.gravity.y, settings.gravity.z);
    P.dragPerMass = guardDragPerMass(dt);
    P.keep = settings.air.model == AirModel::Keserica ? 1.f - settings.air.kesericaFactor : 1.f;
    P.verletKeep = 1.f - settings.time.verletFriction;
    P.verletStart = settings.time.integrator == Integrator::Verlet && !scratch_.verletRunning;
    scratch_.verletRunning = settings.time.integrator == Integrator::Verlet;
    if (scratch_.verletRunning) scratch_.verletKick.resize(n, Vec3::Zero()); // torn-off copies start at 0
    P.verletKick = scratch_.verletKick.data();
    P.dt = dt;
    Vec3* x = cloth.x.data();
    Vec3* v = cloth.v.data();
    Vec3* xPrev = cloth.xPrev.data();
    const float* invMass = cloth.invMass.data();
    PackedParticle* packed = scratch_.packed.data();
    auto& acc = scratch_.threadAcc;
    const auto* ranges = scratch_.threadRange.data();
    uint64_t pinned[kMaxThreadSlots] = {};
    parallelRegion(n, threads, [&](int t, int nt) {
        const Chunk c = chunkOf(n, t, nt);
        uint64_t h = 0;
        switch (settings.time.integrator) {
        case Integrator::SemiImplicitEuler:
            h = integrateKernel<Integrator::SemiImplicitEuler>(c, P, x, v, xPrev, packed, invMass, acc, ranges);
            break;
        case Integrator::ForwardEuler:
            h = integrateKernel<Integrator::ForwardEuler>(c, P, x, v, xPrev, packed, invMass, acc, ranges);
            break;
        case Integrator::Verlet:
            h = integrateKernel<Integrator::Verlet>(c, P, x, v, xPrev, packed, invMass, acc, ranges);
            break;
        default: break; // the references go through phaseIntegrateReference
        }
        pinned[t % kMaxThreadSlots] += h;
    });
    uint64_t signature = n;
    for (uint64_t h : pinned) signature += h;
    scratch_.pinSignature = signature;
    moveDrivers(dt);
}

// The reference integrators (implicit_euler.h, xpbd.h): springs with their full stiffness (no
// stability guard), gravity, air and the wind phase's forces, summed out of (and cleared from) the
// per-thread buffers. Afterwards the packed copy and the pin signature are left as the explicit
// integrator leaves them, for the limit phase and the caches.
void World::phaseIntegrateReference(float dt) {
    refreshSpringCache(dt); // the strain scan reads its ends and rest lengths
    const size_t n = cloth.particleCount();
    std::vector<Vec3>& ext = scratch_.externalForce;
    ext.clear();
    for (size_t t = 0; t < scratch_.threadAcc.size(); ++t) {
        const auto [lo, hi] = scratch_.threadRange[t];
        if (lo >= hi) continue;
        if (ext.empty()) ext.assign(n, Vec3::Zero());
        for (size_t p = lo; p < hi; ++p) {
            ext[p] += scratch_.threadAcc[t][p].head<3>();
            scratch_.threadAcc[t][p].setZero();
        }
    }
    const MaterialSettings& m = settings.material;
    // Implicit Euler treats air drag implicitly (stable at any value); XPBD applies it explicitly,
    // capped by the guard like the explicit integrators.
    const float drag = settings.time.integrator == Integrator::Xpbd ? guardDragPerMass(dt)
                       : settings.air.model == AirModel::Drag      ? settings.air.dragCoefficient / cloth.density
                                                                   : 0.f;
    ReferenceStepInput in{dt,
                          Vec3(settings.gravity.x, settings.gravity.y, settings.gravity.z),
                          drag,
                          settings.air.model == AirModel::Keserica ? 1.f - settings.air.kesericaFactor : 1.f,
                          {SpringKind{cloth.springs, m.stretchStiffness, m.stretchDamping},
                           SpringKind{cloth.bends, m.bendStiffness, m.bendDamping}},
                          ext};
    if (settings.time.integrator == Integrator::ImplicitEuler) {
        auto& holder = scratch_.implicit;
        if (!holder.cache) holder.cache = std::make_unique<ImplicitEulerCache>();
        const ImplicitEulerOptions options{settings.time.cgTolerance, settings.time.cgMaxIterations};
        implicitEulerStep(cloth, in, options, *holder.cache);
        profile.solverIterations += uint64_t(holder.cache->lastIterations);
    } else {
        xpbdStep(cloth, in, scratch_.xpbdDx);
    }
    uint64_t signature = n;
    for (Index p = 0; p < n; ++p) {
        if (cloth.invMass[p] == 0.f) signature += hashIndex(p);
        scratch_.packed[p] = PackedParticle{{cloth.x[p].x(), cloth.x[p].y(), cloth.x[p].z(), 0.f},
                                            {cloth.v[p].x(), cloth.v[p].y(), cloth.v[p].z(), 0.f}};
    }
    scratch_.pinSignature = signature;
    scratch_.verletRunning = false;
    moveDrivers(dt);
}

// ============================================================================================ [LIMIT]

namespace {

inline float sq(float a) { return a * a; }

// Springs within this fraction over their limit count as done: at rest every vertical spring sits
// at the limit, and without a tolerance half of them would be "violated" by round-off each pass
// (at rest the springs then sit within 0.2% of their limit: strain 0.1022 for max_stretch 0.1).
constexpr float kLimitTolerance = 2e-3f;

// Tethers hold a particle this fraction inside the reach the spring limits allow. A tether exactly
// at that reach makes every spring on the path tight at rest: the Jacobi passes then chase
// round-off from the anchors down a dozen rows every sub-step (hundreds of springs per pass).
// Inside, the springs hanging from the tethers stay below their limit (1%: the curtain hangs at
// 8.9% instead of 10% stretch; 0.2% left a cascade of a few hundred springs per pass at 128x128).
constexpr float kTetherSlack = 1e-2f;

// What a limit pass needs, fixed for the sub-step.
struct LimitParams {
    float maxRatio;      // 1 + max_stretch
    float heldRatio;     // 1 + the strain a ball may stretch the springs it touches to (tear threshold)
    float tearRatio;     // 1 + tear threshold (1e30 without tearing)
    float weakRatio;     // 1 + the lowest threshold for weak points and one-point connections
    float relaxation;
    float dt;
    bool limiting;       // limit.enabled with iterations > 0 (else: strain scan only)
    bool velocityFix;    // inelastic fix; off for Verlet, whose v is (x - x_prev) / dt: a move is a velocity
};

// Corrections of one thread: xyz sum and the number of springs in w.
using Corr = Eigen::Vector4f;

// Counts the correction spring s will give its ends (sweep 1 of a pass). Pinned ends get nothing
// (not even a count), so the limit never writes a pinned particle: the tethers read their anchors
// while other threads apply corrections. False if both ends are pinned. Particles getting their
// first count of the pass go on `touched`.
inline bool countCorrection(const Spring& s, const float* invMass, Corr* corr, std::vector<Index>& touched) {
    const float wa = invMass[s.a], wb = invMass[s.b];
    if (wa + wb == 0.f) return false;
    if (wa > 0.f) {
        if (corr[s.a].w() == 0.f) touched.push_back(s.a);
        corr[s.a].w() += 1.f;
    }
    if (wb > 0.f) {
        if (corr[s.b].w() == 0.f) touched.push_back(s.b);
        corr[s.b].w() += 1.f;
    }
    return true;
}

// Provot correction of spring s (longer than maxLen), split by inverse mass, over-relaxed and
// divided by `share` (the larger count of corrections its two ends get this pass), into `corr`.
// Both ends get the same fraction of one correction pair, so the pass conserves momentum, as
// Provot's pairwise correction does (dividing each particle's sum by its own count would not).
// With the velocity fix, `corrV` gets an inelastic velocity change, again as an equal and opposite
// pair: the ends' separating speed along the spring is cancelled, up to correction / dt, never
// reversed. (Turning the whole correction into velocity, v += delta / dt, would inject energy when
// a long overstretched spring is pulled back and set off tear cascades.)
inline void addCorrection(const Spring& s, const Vec3& d, float len2, float maxLen, float share, const float* invMass,
                          const Vec3* v, const LimitParams& P, Corr* corr, Corr* corrV) {
    const float wa = invMass[s.a], wb = invMass[s.b];
    const float len = std::sqrt(len2);
    const float excess = (len - maxLen) * P.relaxation / share;
    const Vec3 n = d / len;
    const Vec3 c = n * (excess / (wa + wb));
    corr[s.a].head<3>() += wa * c;
    corr[s.b].head<3>() -= wb * c;
    if (!P.velocityFix) { // Verlet: v is the position change over dt, so the move is a velocity change
        corrV[s.a].head<3>() += (wa / P.dt) * c;
        corrV[s.b].head<3>() -= (wb / P.dt) * c;
        return;
    }
    const float separating = (v[s.b] - v[s.a]).dot(n);
    if (!(separating > 0.f)) return;
    const Vec3 dv = n * (std::min(separating, excess / P.dt) / (wa + wb));
    corrV[s.a].head<3>() += wa * dv;
    corrV[s.b].head<3>() -= wb * dv;
}

// Applies the corrections of the particles on the `touched` lists of threads [0, nt) that `mine`
// accepts (each particle is accepted by exactly one caller), clears what it read (the buffers are
// zero between passes), and lists the particles it moved in `moved`, stamped in movedIn.
template <class Mine>
inline void applyCorrections(const std::vector<std::vector<Index>>& touched, std::vector<std::vector<Corr>>& corr,
                             std::vector<std::vector<Corr>>& corrV, int nt, Mine mine, Vec3* x, Vec3* v,
                             uint32_t* movedIn, uint32_t stamp, std::vector<Index>& moved) {
    for (int k = 0; k < nt; ++k)
        for (Index p : touched[k]) {
            if (!mine(p) || corr[k][p].w() == 0.f) continue; // not ours, or done from an earlier list
            Corr sum = Corr::Zero(), dv = Corr::Zero();
            for (int j = k; j < nt; ++j) {
                sum += corr[j][p];
                dv += corrV[j][p];
                corr[j][p].setZero();
                corrV[j][p].setZero();
            }
            x[p] += sum.head<3>();
            v[p] += dv.head<3>();
            movedIn[p] = stamp;
            moved.push_back(p);
        }
}

} // namespace

// Rebuilds the limit cache when the topology, the pinned particles or the drivers changed. Tether
// anchors are the pinned particles that no driver moves: a tether to a moving clamp would drag the
// cloth along with it and put all the stretch at the border between the clamp's particles and the
// others.
void World::refreshLimitCache() {
    LimitCache& C = scratch_.limit;
    uint64_t key = hashIndex(cloth.topologyRevision) + hashIndex(scratch_.pinSignature ^ 0x5bd1e995u) +
                   hashIndex(uint64_t(uintptr_t(cloth.springs.data())) ^ 0xc2b2ae35u);
    for (const Driver& d : drivers)
        for (Index p : d.particles) key += hashIndex(uint64_t(p) << 20 | 7u);
    if (key == C.key && C.anchor.size() == cloth.particleCount() && C.listed.size() == cloth.springs.size()) return;
    std::vector<uint8_t> anchor(cloth.particleCount(), 0);
    for (Index p = 0; p < cloth.particleCount(); ++p) anchor[p] = cloth.invMass[p] == 0.f;
    for (const Driver& d : drivers)
        for (Index p : d.particles)
            if (p < anchor.size()) anchor[p] = 0;
    buildLimitCache(cloth, anchor, C);
    C.key = key;
}

// Provot length limiting (Onal 2.1.1): a spring longer than rest * (1 + maxStretch) pulls its ends
// together, split by inverse mass; pinned ends never move. Corrections are Jacobi (each spring's
// divided by the larger number of corrections its ends get, so momentum is conserved) and
// over-relaxed, so the result does not depend on spring order: a fixed row-major Gauss-Seidel
// sweep over stiff links is what makes some solvers blow up at high resolution.
// A spring that tears this sub-step is left alone (Onal 3.2): the first pass records every spring at
// or above its tear threshold (the tear phase's candidates) and skips them. If there are more than
// tear.max_per_step candidates, only the most strained max_per_step are exempt; the later passes
// limit the others, so a spring is never left unlimited without being torn (that ran away).
//
// Order and cost, all in one parallel region. (1) The strain scan reads every structural spring
// once (four at a time, step_kernels.h); most leave after one squared-length compare, no square
// root. It lists the candidates and the springs over the limit. (2) On cloths the passes alone
// cannot hold (tethers.h: sag index), the tethers pull every particle back within reach of its
// anchor. A tether whose path runs through a tear candidate does not pull this sub-step; the scan
// comes first so that a spring reaching its threshold is seen before anything pulls it back.
// (3) The Jacobi passes work on the listed springs only: a pass drops the springs back within the
// limit (to kLimitTolerance) and lists the springs of the particles it moved that it pushed over
// (particle-spring table), so a pass covers what a full pass would correct; they stop when a pass
// corrects nothing. At rest that is a few hundred springs, not all of them, per sub-step.
void World::phaseLimit(float dt) {
    const size_t n = cloth.particleCount();
    const size_t ns = cloth.springs.size();
    const int threads = int(scratch_.threadAcc.size());
    const LimitSettings& L = settings.limit;
    const TearSettings& TS = settings.tear;
    LimitParams P;
    P.limiting = L.enabled && L.iterations > 0;
    P.maxRatio = 1.f + L.maxStretch;
    P.tearRatio = TS.enabled ? 1.f + TS.threshold : 1e30f;
    // Weak points and one-point connections tear at their own (lower) thresholds (Onal 3.2.2, 3.2.3).
    P.weakRatio = TS.enabled ? 1.f + std::min({TS.weakThreshold, TS.onePointThreshold, TS.threshold}) : 1e30f;
    P.relaxation = L.relaxation;
    P.dt = dt;
    P.velocityFix = settings.time.integrator != Integrator::Verlet;
    const float minTearRatio = std::min(P.tearRatio, P.weakRatio);
    P.heldRatio = std::max(P.maxRatio, 1.f + TS.threshold);
    const float doneRatio = P.maxRatio * (1.f + kLimitTolerance);
    const float heldDoneRatio = P.heldRatio * (1.f + kLimitTolerance);
    // Particles under a ball (collide phase): the ball, not the limit, decides where they are, up to
    // the tear threshold on their springs, so a ball pressing on the cloth can stretch it and tear it
    // (Onal 4.1). Tethers through them do not pull either: what hangs below a ball hangs from it.
    const std::vector<BallContact>& contacts = scratch_.contacts;
    // The scan flags springs over the limit and those over a tear threshold (which may be lower).
    const float scanRatio = std::min(P.limiting ? doneRatio : 1e30f, minTearRatio);
    // The scan reads the spring cache and packed positions (from phaseSprings and the integrator).
    const SpringCache& S = scratch_.springs;
    const SpringArrays arrays{S.a16.data(), S.b16.data(), S.rest.data(), S.k.data(), S.kd.data()};
    const PackedParticle* packed = scratch_.packed.data();
    // Lists shorter than this are worked by one thread (a barrier costs more than the work).
    constexpr size_t kSerialList = 2048;

    Vec3* x = cloth.x.data();
    Vec3* v = cloth.v.data();
    const float* invMass = cloth.invMass.data();
    const uint8_t* flags = cloth.flags.data();
    const Spring* springs = cloth.springs.data();
    auto& corr = scratch_.threadCorr;
    auto& corrV = scratch_.threadCorrV;
    auto& active = scratch_.threadActive;
    auto& moved = scratch_.threadMoved;
    auto& touched = scratch_.threadTouched;
    auto& found = scratch_.threadFound;
    if (corr.size() != size_t(threads)) corr.resize(threads);
    if (corrV.size() != size_t(threads)) corrV.resize(threads);
    for (auto& c : corr)
        if (c.size() != n) c.resize(n, Corr::Zero());
    for (auto& c : corrV)
        if (c.size() != n) c.resize(n, Corr::Zero());
    active.resize(threads);
    moved.resize(threads);
    touched.resize(threads);
    found.resize(threads);
    for (int t = 0; t < threads; ++t) {
        active[t].clear();
        moved[t].clear();
        found[t].clear();
    }
    if (P.limiting) refreshLimitCache();
    LimitCache& C = scratch_.limit;
    uint8_t* listed = P.limiting ? C.listed.data() : nullptr;
    uint32_t* movedIn = P.limiting ? C.moved.data() : nullptr;
    const float gravity = Vec3(settings.gravity.x, settings.gravity.y, settings.gravity.z).norm();
    const bool useTethers = P.limiting && sagIndex(C.depth, gravity, dt, L.iterations, C.meanRest) > kTetherSagIndex;
    const uint32_t stamp0 = C.stamp;
    if (P.limiting) C.stamp += uint32_t(L.iterations);

    size_t listSize[kMaxThreadSlots] = {};
    int work[kMaxThreadSlots] = {};
    float exemptStrain = -1.f; // with too many candidates: those below this strain are limited

    // Is spring i over its limit (by more than the tolerance)? Exempt if it is a candidate that
    // tears this sub-step.
    auto underBall = [&](const Spring& s) { return ((flags[s.a] | flags[s.b]) & kTouched) != 0; };
    auto overLimit = [&](const Spring& s, float len2) {
        return len2 > sq(s.rest * (underBall(s) ? heldDoneRatio : doneRatio));
    };
    // A spring too short to halve is limited even as a candidate: if its tear fails (no weak-point
    // path, too short for a basic tear) it must not stay overstretched.
    const float minSplitRest = cloth.minSplitRest;
    auto exempt = [&](const Spring& s, float len2) {
        if (len2 < sq(s.rest * minTearRatio) || s.rest < minSplitRest) return false;
        const bool weak = (flags[s.a] | flags[s.b]) & (kWeak | kHinge);
        return len2 >= sq(s.rest * (weak ? P.weakRatio : P.tearRatio)) && std::sqrt(len2) / s.rest - 1.f >= exemptStrain;
    };
    // A Jacobi pass is two sweeps over the lists. Sweep 1 drops the springs back within the limit
    // and counts the corrections each particle gets (into buffer c). Sweep 2 adds the corrections,
    // each spring's divided by the larger total count of its ends (over all `nc` count buffers).
    auto count1 = [&](std::vector<Index>& l, Corr* c, std::vector<Index>& touched) {
        int corrected = 0;
        size_t keep = 0;
        for (Index i : l) {
            const Spring& s = springs[i];
            const float len2 = (x[s.b] - x[s.a]).squaredNorm();
            if (!overLimit(s, len2)) {
                listed[i] = 0;
                continue;
            }
            l[keep++] = i;
            if (!exempt(s, len2)) corrected += countCorrection(s, invMass, c, touched);
        }
        l.resize(keep);
        return corrected;
    };
    auto correct1 = [&](const std::vector<Index>& l, Corr* c, Corr* cv, int nc) {
        for (Index i : l) {
            const Spring& s = springs[i];
            if (invMass[s.a] + invMass[s.b] == 0.f) continue;
            const Vec3 d = x[s.b] - x[s.a];
            const float len2 = d.squaredNorm();
            if (exempt(s, len2)) continue;
            float ca = 0.f, cb = 0.f;
            for (int k = 0; k < nc; ++k) {
                ca += corr[k][s.a].w();
                cb += corr[k][s.b].w();
            }
            addCorrection(s, d, len2, s.rest * (underBall(s) ? P.heldRatio : P.maxRatio), std::max(ca, cb), invMass,
                          v, P, c, cv);
        }
    };
    // Lists the springs of the particles in `m` that a pass pushed over the limit. A spring whose
    // two ends both moved is listed from its lower-numbered end only.
    auto expand = [&](const std::vector<Index>& m, uint32_t stamp, std::vector<Index>& l) {
        for (Index p : m)
            for (uint32_t k = C.springStart[p]; k < C.springStart[p + 1]; ++k) {
                const Index i = C.springOf[k];
                if (listed[i]) continue;
                const Spring& s = springs[i];
                const Index q = s.a == p ? s.b : s.a;
                if (q < p && movedIn[q] == stamp) continue;
                if (overLimit(s, (x[s.b] - x[s.a]).squaredNorm())) {
                    listed[i] = 1;
                    l.push_back(i);
                }
            }
    };

    int cappedSprings = 0; // springs the last allowed pass still corrected (thread 0 writes it)
    parallelRegion(std::max(ns, n), threads, [&](int t, int nt) {
        // ---- strain scan: every spring once, most of them with one compare and no square root
        std::vector<Index>& list = active[t];
        const Chunk sc = chunkOf(ns, t, nt);
        scanSprings(arrays, sc.begin, sc.end, scanRatio, packed, [&](size_t e, float len2) {
            const Index i = S.index[e];
            const Spring& s = springs[i];
            if (len2 >= sq(s.rest * minTearRatio)) {
                const bool weak = (flags[s.a] | flags[s.b]) & (kWeak | kHinge);
                if (len2 >= sq(s.rest * (weak ? P.weakRatio : P.tearRatio)))
                    found[t].push_back(TearCandidate{Index(i), std::sqrt(len2) / s.rest - 1.f});
            }
            if (P.limiting && overLimit(s, len2)) {
                listed[i] = 1;
                list.push_back(Index(i));
            }
        });
        if (!P.limiting) return;
        parallelBarrier(nt); // candidates complete

        // ---- tethers, on this thread's particles: their anchors are pinned, so nothing another
        // thread does moves what this one reads. First find the tethers that must not pull.
        size_t candidates = 0;
        for (int k = 0; k < nt; ++k) candidates += found[k].size();
        const bool anyFound = candidates > 0 || !contacts.empty();
        if (anyFound) {
            if (t == 0) {
                if (useTethers) {
                    std::vector<Index> seeds;
                    for (int k = 0; k < nt; ++k)
                        for (const TearCandidate& f : found[k]) {
                            seeds.push_back(springs[f.spring].a);
                            seeds.push_back(springs[f.spring].b);
                        }
                    for (const BallContact& c : contacts)
                        for (Index p : cloth.triangles[c.triangle].p) seeds.push_back(p);
                    markTethersThrough(C, seeds, C.cut);
                }
                // More candidates than tear.max_per_step: only the most strained are exempt.
                if (candidates > size_t(TS.maxPerStep)) {
                    std::vector<float> strains;
                    for (int k = 0; k < nt; ++k)
                        for (const TearCandidate& f : found[k]) strains.push_back(f.strain);
                    std::nth_element(strains.begin(), strains.begin() + (TS.maxPerStep - 1), strains.end(),
                                     std::greater<>());
                    exemptStrain = strains[TS.maxPerStep - 1];
                }
            }
            parallelBarrier(nt);
        }
        const uint8_t* cut = anyFound ? C.cut.data() : nullptr;
        const Chunk pc = chunkOf(n, t, nt);
        if (useTethers)
            tetherKernel(pc.begin, pc.end, C.tether.data(), C.length.data(), cut, P.maxRatio * (1.f - kTetherSlack),
                         P.dt, P.velocityFix, packed, x, v);

        // ---- Jacobi passes over the listed springs, until none is over the limit
        for (int pass = 0; pass < L.iterations; ++pass) {
            const uint32_t stamp = stamp0 + uint32_t(pass) + 1;
            listSize[t] = list.size();
            parallelBarrier(nt); // lists, positions and listSize[] complete
            size_t total = 0;
            for (int k = 0; k < nt; ++k) total += listSize[k];
            if (total == 0) break;
            if (total < kSerialList || nt == 1) {
                // Thread 0 works every list, in thread order, into its own buffer.
                if (t == 0) {
                    int corrected = 0;
                    touched[0].clear();
                    for (int k = 0; k < nt; ++k) corrected += count1(active[k], corr[0].data(), touched[0]);
                    for (int k = 0; k < nt; ++k) correct1(active[k], corr[0].data(), corrV[0].data(), 1);
                    moved[0].clear();
                    applyCorrections(touched, corr, corrV, 1, [](Index) { return true; }, x, v, movedIn, stamp,
                                     moved[0]);
                    expand(moved[0], stamp, active[0]);
                    work[0] = corrected;
                    for (int k = 1; k < nt; ++k) work[k] = 0;
                }
            } else {
                touched[t].clear();
                work[t] = count1(list, corr[t].data(), touched[t]);
                parallelBarrier(nt); // counts complete
                correct1(list, corr[t].data(), corrV[t].data(), nt);
                parallelBarrier(nt); // corrections complete
                moved[t].clear();
                auto mine = [&](Index p) { return p >= pc.begin && p < pc.end; };
                applyCorrections(touched, corr, corrV, nt, mine, x, v, movedIn, stamp, moved[t]);
                parallelBarrier(nt); // positions and stamps complete
                expand(moved[t], stamp, list);
            }
            parallelBarrier(nt); // work[] complete
            int corrected = 0;
            for (int k = 0; k < nt; ++k) corrected += work[k];
            if (corrected == 0) break;
            if (t == 0 && pass + 1 == L.iterations) cappedSprings = corrected;
        }
        // Springs still listed (iteration cap, exempt candidates) leave their lists.
        parallelBarrier(nt);
        for (Index i : list) listed[i] = 0;
    });

    if (cappedSprings > 0) {
        profile.limitCapped++;
        profile.limitCappedSprings += uint64_t(cappedSprings);
    }
    // Tear candidates, merged in thread order (deterministic).
    scratch_.tearCandidates.clear();
    for (auto& f : found) scratch_.tearCandidates.insert(scratch_.tearCandidates.end(), f.begin(), f.end());
}

// ============================================================================================= [TEAR]

void World::phaseTear() {
    std::vector<std::pair<Index, Index>> copies;
    TearContext ctx{settings.tear, time, &tearLog, &copies};
    tearSprings(cloth, scratch_.tearCandidates, ctx);
    // A particle duplicated by a tear keeps following whatever drove the original.
    for (const auto& [original, copy] : copies)
        for (Driver& d : drivers)
            if (std::find(d.particles.begin(), d.particles.end(), original) != d.particles.end())
                d.particles.push_back(copy);
}

// ========================================================================================= [COLLIDE]

// The ball broad phase needs a bound on every triangle edge (collide.cpp, trianglesIn). With tearing,
// a spring past its tear threshold tears in this sub-step's tear phase; with the limit alone, none
// stays past the limit; the factor 2 covers what one sub-step of motion adds before the limit and
// the tear phase run. Without either, no bound: every triangle is tested.
float World::ballEdgeBound() const {
    const TearSettings& T = settings.tear;
    float strain = std::numeric_limits<float>::infinity();
    if (T.enabled) strain = std::max({T.threshold, T.weakThreshold, T.onePointThreshold});
    else if (settings.limit.enabled && settings.limit.iterations > 0) strain = settings.limit.maxStretch;
    if (!ballBroadPhase || scratch_.springs.maxRest <= 0.f) strain = std::numeric_limits<float>::infinity();
    return 2.f * scratch_.springs.maxRest * (1.f + strain);
}

void World::phaseCollide(float dt) {
    const Vec3 g(settings.gravity.x, settings.gravity.y, settings.gravity.z);
    collideBalls(cloth, balls, settings.collision, g, dt, ballEdgeBound(), scratch_.packed.data(), scratch_.contacts);
}

void World::phaseContact(float dt) {
    // Without limiting nothing holds the cloth back against a ball: the collide phase said it all.
    const bool held = settings.limit.enabled && settings.limit.iterations > 0;
    settleContacts(cloth, balls, settings.collision, dt, ballEdgeBound(), held, scratch_.contacts, scratch_.contactOf);
    scratch_.contacts.clear();
}

// ============================================================================================= [MISC]

// After phase `after` (-1: before the sub-step's first phase, i.e. set from outside the step): the
// first non-finite value, with the phase, frame and time, into nonFiniteWhere. The force buffers are
// read after the phases that fill them (springs, wind); the integrator clears them.
void World::checkFinite(int after) {
    if (!finite) return; // the first one is the one to trace
    const bool forces = after == int(Phase::Springs) || after == int(Phase::Wind);
    const std::string what = findNonFinite(cloth, balls, forces ? &scratch_.threadAcc : nullptr);
    if (what.empty()) return;
    finite = false;
    const std::string where = after < 0 ? std::string("before a sub-step (set from outside the step)")
                                        : std::string("after phase '") + phaseName(Phase(after)) + "'";
    nonFiniteWhere = where + " at frame " + std::to_string(steps) + ", t = " + std::to_string(time) + " s: " + what;
}

// Once per frame: the largest structural strain (compared as squared length ratios, one square
// root at the end) and the first non-finite particle, both split over the threads.
void World::phaseBookkeeping() {
    PhaseTimer t(profile, Phase::Bookkeeping);
    const size_t ns = cloth.springs.size(), n = cloth.particleCount();
    const int threads = threadsFor(n);
    float worstLen2[kMaxThreadSlots], worstRest2[kMaxThreadSlots];
    size_t firstBad[kMaxThreadSlots];
    float speed2[kMaxThreadSlots];
    const bool checkFinite = finite;
    parallelRegion(std::max(ns, n), threads, [&](int t, int nt) {
        const Chunk c = chunkOf(ns, t, nt);
        float len2Max = 0.f, rest2Max = 1.f; // ratio len2Max / rest2Max, kept without dividing
        for (size_t i = c.begin; i < c.end; ++i) {
            const Spring& s = cloth.springs[i];
            const float len2 = (cloth.x[s.b] - cloth.x[s.a]).squaredNorm(), rest2 = s.rest * s.rest;
            if (len2 * rest2Max > len2Max * rest2) len2Max = len2, rest2Max = rest2;
        }
        worstLen2[t] = len2Max;
        worstRest2[t] = rest2Max;
        firstBad[t] = n;
        speed2[t] = 0.f;
        if (!checkFinite) return;
        const Chunk pc = chunkOf(n, t, nt);
        float fastest = 0.f; // for sleep.cpp
        for (size_t p = pc.begin; p < pc.end; ++p) {
            if (!cloth.x[p].allFinite() || !cloth.v[p].allFinite()) {
                firstBad[t] = p;
                break;
            }
            fastest = std::max(fastest, cloth.v[p].squaredNorm());
        }
        speed2[t] = fastest;
    });
    const int used = (threads > 1 && std::max(ns, n) >= kParallelWork) ? threads : 1;
    float worst = 0.f, fastest2 = 0.f;
    size_t bad = n;
    for (int k = 0; k < used; ++k) {
        worst = std::max(worst, std::sqrt(worstLen2[k] / worstRest2[k]) - 1.f);
        bad = std::min(bad, firstBad[k]);
        fastest2 = std::max(fastest2, speed2[k]);
    }
    maxStrain = worst;
    maxSpeed = checkFinite ? std::sqrt(fastest2) : std::numeric_limits<float>::infinity();
    if (finite) {
        if (bad < n) {
            finite = false;
            nonFiniteWhere = "particle " + std::to_string(bad) + " at frame " + std::to_string(steps);
        }
        for (const Ball& b : balls)
            if (!b.x.allFinite() || !b.v.allFinite()) finite = false;
    }
}

int World::applyImpulse(const Vec3& center, float radius, const Vec3& direction, float dv) {
    Vec3 dir = direction;
    if (dir.squaredNorm() == 0.f) return 0;
    dir.normalize();
    wake();
    int hit = 0;
    for (Index p = 0; p < cloth.particleCount(); ++p) {
        if (cloth.invMass[p] == 0.f || (cloth.x[p] - center).squaredNorm() > radius * radius) continue;
        cloth.v[p] += dv * dir;
        // Verlet keeps velocity implicitly in x - xPrev.
        cloth.xPrev[p] -= dv * dir * (settings.time.frameDt / float(settings.time.substeps));
        ++hit;
    }
    return hit;
}

double World::kineticEnergy() const {
    double e = 0;
    for (Index p = 0; p < cloth.particleCount(); ++p) e += 0.5 * cloth.particleMass(p) * cloth.v[p].squaredNorm();
    for (const Ball& b : balls) e += 0.5 * b.mass * b.v.squaredNorm();
    return e;
}

double World::potentialEnergy() const {
    const Vec3d g(settings.gravity.x, settings.gravity.y, settings.gravity.z);
    double e = 0;
    for (Index p = 0; p < cloth.particleCount(); ++p) e -= cloth.particleMass(p) * g.dot(cloth.x[p].cast<double>());
    auto springEnergy = [&](const std::vector<Spring>& springs, float k) {
        for (const Spring& s : springs) {
            const double ext = (cloth.x[s.b] - cloth.x[s.a]).norm() - s.rest;
            e += 0.5 * k * s.weight * ext * ext;
        }
    };
    springEnergy(cloth.springs, settings.material.stretchStiffness);
    springEnergy(cloth.bends, settings.material.bendStiffness);
    return e;
}

} // namespace clothtear
