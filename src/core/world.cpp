// The step: named, timed phases over flat arrays. See world.h for the phase list.
//
// Section index:
//   [SETUP]      rebuild, pinning, settings
//   [STEP]       step / substep and the phase driver
//   [FORCES]     gravity, air friction, spring forces, wind
//   [INTEGRATE]  semi-implicit Euler, forward Euler, Verlet
//   [LIMIT]      Provot length limiting (averaged Jacobi), fused with the strain scan
//   [MISC]       impulse, energy, bookkeeping
#include "clothtear/world.h"

#include "clothtear/tear.h"
#include "collide.h"
#include "parallel.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace clothtear {

const char* phaseName(Phase p) {
    static const char* names[] = {"forces", "springs", "wind", "integrate", "limit", "collide", "tear", "bookkeeping"};
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

// Threads worth using for a cloth of n particles (forking costs a few microseconds).
int threadsFor(size_t particles) { return particles >= 2048 ? maxThreads() : 1; }

// Spring force along the spring (Hooke + damping of the relative velocity along it), on particle a:
//   f = (k (L - L0) + kd (v_b - v_a).n) n,  n = (x_b - x_a) / L;  particle b gets -f.
inline Vec3 springForce(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb, float rest, float k, float kd) {
    const Vec3 d = xb - xa;
    const float len = d.norm();
    if (!(len > 1e-12f)) return Vec3::Zero();
    const Vec3 n = d / len;
    return (k * (len - rest) + kd * (vb - va).dot(n)) * n;
}

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
    for (int i = 0; i < settings.time.substeps; ++i) substep();
    phaseBookkeeping();
    ++steps;
}

void World::substep() {
    const float dt = settings.time.frameDt / float(settings.time.substeps);
    const bool needCollide = !balls.empty() || settings.collision.ground;
    {
        PhaseTimer t(profile, Phase::Forces);
        phaseForces(dt);
    }
    {
        PhaseTimer t(profile, Phase::Springs);
        phaseSprings(dt);
    }
    if (settings.wind.enabled && settings.wind.speed > 0.f && settings.wind.dragCoefficient > 0.f) {
        PhaseTimer t(profile, Phase::Wind);
        phaseWind();
    }
    {
        PhaseTimer t(profile, Phase::Integrate);
        phaseIntegrate(dt);
    }
    // The limit pass doubles as the strain scan, so it runs when either needs it.
    if ((settings.limit.enabled && settings.limit.iterations > 0) || settings.tear.enabled) {
        PhaseTimer t(profile, Phase::Limit);
        phaseLimit(dt);
    }
    if (needCollide) {
        PhaseTimer t(profile, Phase::Collide);
        phaseCollide(dt);
    }
    if (settings.tear.enabled && !scratch_.tearCandidates.empty()) {
        PhaseTimer t(profile, Phase::Tear);
        phaseTear();
    }
    time += dt;
    profile.substeps++;
}

// =========================================================================================== [FORCES]

// External per-particle forces, and clearing the per-thread scatter buffers.
// Air friction, physical model: F = -c A v with A the particle's area share, so a = -(c / density) v
// whatever the resolution. (Keserica's "10% per step" model is applied in the integrator instead.)
void World::phaseForces(float /*dt*/) {
    const size_t n = cloth.particleCount();
    const int threads = threadsFor(n);
    scratch_.force.resize(n);
    scratch_.threadAcc.resize(threads);
    for (auto& acc : scratch_.threadAcc) acc.resize(n);
    const Vec3 g(settings.gravity.x, settings.gravity.y, settings.gravity.z);
    const float dragPerMass = settings.air.model == AirModel::Drag ? settings.air.dragCoefficient / cloth.density : 0.f;
    Vec3* force = scratch_.force.data();
    const Vec3* v = cloth.v.data();
    auto& acc = scratch_.threadAcc;
    parallelRegion(n, threads, [&](int t, int nt) {
        const Chunk c = chunkOf(n, t, nt);
        for (size_t p = c.begin; p < c.end; ++p) {
            force[p] = g - dragPerMass * v[p]; // stored as acceleration from external forces
            for (auto& buffer : acc) buffer[p].setZero();
        }
    });
}

// Structural and bend-shear springs, scattered into per-thread buffers (one contiguous chunk of
// springs per thread), summed in the integrator.
//
// Stability guard (time.stability_guard, on by default): explicit integration of a spring is stable
// only while k (1/m_a + 1/m_b) dt^2 stays small. Tearing halves triangles again and again (a midpoint
// particle gets 1/6 of a normal particle's mass on springs of twice the weight), and a finer mesh has
// lighter particles; instead of exploding, each spring's stiffness and damping are capped to
//   k (1/m_a + 1/m_b) dt^2 <= 1/3   and   kd (1/m_a + 1/m_b) dt <= 1/6,
// which keeps a particle with ~8 springs inside the stable region of semi-implicit Euler. A capped
// spring is softer than asked for; the Provot limit still holds its length.
void World::phaseSprings(float dt) {
    const size_t n = cloth.particleCount();
    const int threads = int(scratch_.threadAcc.size());
    const MaterialSettings& m = settings.material;
    const Vec3* x = cloth.x.data();
    const Vec3* v = cloth.v.data();
    const float* invMass = cloth.invMass.data();
    const bool guard = settings.time.stabilityGuard;
    const float kCap = 1.f / (3.f * dt * dt), kdCap = 1.f / (6.f * dt);
    auto scatter = [&](const std::vector<Spring>& springs, float ks, float kd, Vec3* acc, Chunk c) {
        for (size_t i = c.begin; i < c.end; ++i) {
            const Spring& s = springs[i];
            float k = ks * s.weight, damping = kd * s.weight;
            if (guard) {
                const float w = invMass[s.a] + invMass[s.b];
                if (k * w > kCap) k = kCap / w;
                if (damping * w > kdCap) damping = kdCap / w;
            }
            const Vec3 f = springForce(x[s.a], x[s.b], v[s.a], v[s.b], s.rest, k, damping);
            acc[s.a] += f;
            acc[s.b] -= f;
        }
    };
    parallelRegion(n, threads, [&](int t, int nt) {
        Vec3* acc = scratch_.threadAcc[t].data();
        scatter(cloth.springs, m.stretchStiffness, m.stretchDamping, acc, chunkOf(cloth.springs.size(), t, nt));
        if (m.bendStiffness > 0.f || m.bendDamping > 0.f)
            scatter(cloth.bends, m.bendStiffness, m.bendDamping, acc, chunkOf(cloth.bends.size(), t, nt));
    });
}

// Wind on each triangle from its normal and the relative air velocity (so a flag flutters):
//   F = c A (n . v_rel) |n . v_rel| n,   v_rel = wind - mean triangle velocity, shared by the corners.
void World::phaseWind() {
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
    const int threads = int(scratch_.threadAcc.size());
    parallelRegion(cloth.triangles.size(), threads, [&](int t, int nt) {
        Vec3* acc = scratch_.threadAcc[t].data();
        const Chunk c = chunkOf(cloth.triangles.size(), t, nt);
        for (size_t i = c.begin; i < c.end; ++i) {
            const Triangle& tri = cloth.triangles[i];
            const Vec3 cross = (x[tri.p[1]] - x[tri.p[0]]).cross(x[tri.p[2]] - x[tri.p[0]]);
            const float twiceArea = cross.norm();
            if (!(twiceArea > 0.f)) continue;
            const Vec3 nrm = cross / twiceArea;
            const Vec3 vrel = wind - (v[tri.p[0]] + v[tri.p[1]] + v[tri.p[2]]) * (1.f / 3.f);
            const float vn = nrm.dot(vrel);
            const Vec3 f = (w.dragCoefficient * 0.5f * twiceArea * vn * std::abs(vn) / 3.f) * nrm;
            for (Index p : tri.p) acc[p] += f;
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
        }
}

// a = external acceleration + (sum of spring and wind forces) / m.
//   semi-implicit Euler (Onal 2.1):  v += a dt;  x += v dt
//   forward Euler:                   x += v dt;  v += a dt
//   Verlet (Keserica 2.2.1):         x' = x + (1 - f)(x - x_prev) + a dt^2;  v = (x' - x) / dt
// Pinned particles (invMass 0) do not move here; drivers move theirs kinematically.
void World::phaseIntegrate(float dt) {
    const size_t n = cloth.particleCount();
    const int threads = int(scratch_.threadAcc.size());
    const Integrator integrator = settings.time.integrator;
    const float keep = settings.air.model == AirModel::Keserica ? 1.f - settings.air.kesericaFactor : 1.f;
    const float verletKeep = 1.f - settings.time.verletFriction;
    Vec3* x = cloth.x.data();
    Vec3* v = cloth.v.data();
    Vec3* xPrev = cloth.xPrev.data();
    const float* invMass = cloth.invMass.data();
    const Vec3* ext = scratch_.force.data();
    auto& acc = scratch_.threadAcc;
    parallelRegion(n, threads, [&](int t, int nt) {
        const Chunk c = chunkOf(n, t, nt);
        for (size_t p = c.begin; p < c.end; ++p) {
            if (invMass[p] == 0.f) continue;
            Vec3 f = acc[0][p];
            for (size_t k = 1; k < acc.size(); ++k) f += acc[k][p];
            const Vec3 a = ext[p] + f * invMass[p];
            switch (integrator) {
            case Integrator::SemiImplicitEuler:
                v[p] = (v[p] + a * dt) * keep;
                x[p] += v[p] * dt;
                break;
            case Integrator::ForwardEuler:
                x[p] += v[p] * dt;
                v[p] = (v[p] + a * dt) * keep;
                break;
            case Integrator::Verlet: {
                const Vec3 next = x[p] + verletKeep * keep * (x[p] - xPrev[p]) + a * (dt * dt);
                xPrev[p] = x[p];
                x[p] = next;
                v[p] = (next - xPrev[p]) / dt;
                break;
            }
            }
        }
    });
    moveDrivers(dt);
}

// ============================================================================================ [LIMIT]

// Provot length limiting (Onal 2.1.1): a spring longer than rest * (1 + maxStretch) pulls its ends
// together, split by inverse mass; pinned ends never move. Corrections are averaged per particle
// (Jacobi) and over-relaxed, so the result does not depend on spring order: a fixed row-major
// Gauss-Seidel sweep over stiff links is what makes some solvers blow up at high resolution.
// A spring that tears this sub-step is left alone (Onal 3.2): the first pass records every spring at
// or above its tear threshold (the tear phase's candidates) and skips them. If there are more than
// tear.max_per_step candidates, only the most strained max_per_step are exempt; the later passes
// limit the others, so a spring is never left unlimited without being torn (that ran away).
void World::phaseLimit(float dt) {
    const size_t n = cloth.particleCount();
    const size_t ns = cloth.springs.size();
    const int threads = int(scratch_.threadAcc.size());
    const LimitSettings& L = settings.limit;
    const TearSettings& T = settings.tear;
    const bool limiting = L.enabled && L.iterations > 0;
    const float maxRatio = 1.f + L.maxStretch;
    const float tearRatio = T.enabled ? 1.f + T.threshold : 1e30f;
    // Weak points and one-point connections tear at their own (lower) thresholds (Onal 3.2.2, 3.2.3).
    const float weakRatio = T.enabled ? 1.f + std::min({T.weakThreshold, T.onePointThreshold, T.threshold}) : 1e30f;
    const bool velocityFix = settings.time.integrator != Integrator::Verlet; // Verlet derives v from x
    Vec3* x = cloth.x.data();
    Vec3* v = cloth.v.data();
    const float* invMass = cloth.invMass.data();
    const uint8_t* flags = cloth.flags.data();
    const Spring* springs = cloth.springs.data();
    scratch_.threadCount.resize(threads);
    for (auto& c : scratch_.threadCount) c.resize(n);
    auto& acc = scratch_.threadAcc;
    auto& cnt = scratch_.threadCount;

    // Tear candidates of this sub-step, per thread then merged in thread order (deterministic).
    std::vector<std::vector<TearCandidate>> found(threads);
    const int passes = limiting ? L.iterations : 1;
    float exemptStrain = -1.f; // after pass 0: candidates below this strain are limited after all
    for (int pass = 0; pass < passes; ++pass) {
        int violated = 0;
        parallelRegion(n, threads, [&](int t, int nt) {
            const Chunk pc = chunkOf(n, t, nt);
            // Every thread's buffer over this thread's particles (any thread may scatter anywhere).
            for (size_t p = pc.begin; p < pc.end; ++p)
                for (int k = 0; k < nt; ++k) {
                    acc[k][p].setZero();
                    cnt[k][p] = 0.f;
                }
#if CLOTHTEAR_HAVE_OPENMP
            if (nt > 1) {
#pragma omp barrier
            }
#endif
            int localViolated = 0;
            const Chunk c = chunkOf(ns, t, nt);
            for (size_t i = c.begin; i < c.end; ++i) {
                const Spring& s = springs[i];
                const Vec3 d = x[s.b] - x[s.a];
                const float len2 = d.squaredNorm();
                const float maxLen = s.rest * maxRatio;
                const bool weak = (flags[s.a] | flags[s.b]) & (kWeak | kHinge);
                const float tearLen = s.rest * (weak ? weakRatio : tearRatio);
                if (pass == 0 && len2 >= tearLen * tearLen)
                    found[t].push_back(TearCandidate{Index(i), std::sqrt(len2) / s.rest - 1.f});
                if (!limiting || len2 <= maxLen * maxLen) continue;
                if (len2 >= tearLen * tearLen && (pass == 0 || std::sqrt(len2) / s.rest - 1.f >= exemptStrain)) continue;
                const float wa = invMass[s.a], wb = invMass[s.b];
                if (wa + wb == 0.f) continue;
                const float len = std::sqrt(len2);
                const Vec3 corr = d * ((len - maxLen) / (len * (wa + wb)));
                acc[t][s.a] += wa * corr;
                acc[t][s.b] -= wb * corr;
                cnt[t][s.a] += 1.f;
                cnt[t][s.b] += 1.f;
                ++localViolated;
            }
#if CLOTHTEAR_HAVE_OPENMP
            if (nt > 1) {
#pragma omp atomic
                violated += localViolated;
#pragma omp barrier
            } else
#endif
                violated += localViolated;
            if (!limiting) return;
            for (size_t p = pc.begin; p < pc.end; ++p) {
                float count = cnt[0][p];
                Vec3 sum = acc[0][p];
                for (int k = 1; k < nt; ++k) {
                    count += cnt[k][p];
                    sum += acc[k][p];
                }
                if (count == 0.f) continue;
                const Vec3 delta = sum * (L.relaxation / count);
                x[p] += delta;
                // Inelastic velocity fix: cancel the velocity that carried p away from where the
                // limit puts it, up to |delta| / dt, but never add velocity towards it. (Turning the
                // whole correction into velocity, as v += delta / dt would, injects energy when a
                // long overstretched spring is pulled back and set off tear cascades.)
                if (velocityFix) {
                    const float d = delta.norm();
                    if (d > 0.f) {
                        const Vec3 dir = delta / d;
                        const float away = -v[p].dot(dir);
                        if (away > 0.f) v[p] += dir * std::min(d / dt, away);
                    }
                }
            }
        });
        if (pass == 0) {
            size_t total = 0;
            for (const auto& f : found) total += f.size();
            if (total > size_t(T.maxPerStep)) {
                std::vector<float> strains;
                for (const auto& f : found)
                    for (const TearCandidate& k : f) strains.push_back(k.strain);
                std::nth_element(strains.begin(), strains.begin() + (T.maxPerStep - 1), strains.end(), std::greater<>());
                exemptStrain = strains[T.maxPerStep - 1];
                violated += int(total) - T.maxPerStep; // those still need limiting
            }
        }
        if (violated == 0) break;
    }
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

void World::phaseCollide(float dt) {
    const Vec3 g(settings.gravity.x, settings.gravity.y, settings.gravity.z);
    collideBallsAndGround(cloth, balls, settings.collision, g, dt);
}

// ============================================================================================= [MISC]

void World::phaseBookkeeping() {
    PhaseTimer t(profile, Phase::Bookkeeping);
    float worst = 0.f;
    for (const Spring& s : cloth.springs) {
        const float len = (cloth.x[s.b] - cloth.x[s.a]).norm();
        worst = std::max(worst, len / s.rest - 1.f);
    }
    maxStrain = worst;
    if (finite) {
        for (Index p = 0; p < cloth.particleCount(); ++p)
            if (!cloth.x[p].allFinite() || !cloth.v[p].allFinite()) {
                finite = false;
                nonFiniteWhere = "particle " + std::to_string(p) + " at frame " + std::to_string(steps);
                break;
            }
        for (const Ball& b : balls)
            if (!b.x.allFinite() || !b.v.allFinite()) finite = false;
    }
}

int World::applyImpulse(const Vec3& center, float radius, const Vec3& direction, float dv) {
    Vec3 dir = direction;
    if (dir.squaredNorm() == 0.f) return 0;
    dir.normalize();
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
