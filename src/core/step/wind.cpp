// The wind phase: quadratic drag of the relative air velocity on every triangle (Keserica 5).
#include "kernels.h"
#include "parallel.h"
#include "phases.h"

#include <algorithm>
#include <cmath>

namespace clothtear {
namespace {

// The wind cache follows the topology (corners, rest areas) and the inverse masses (the guard's
// cap). Each thread's chunk of triangles touches a band of particles; the integrator reads a
// thread's force buffer only there.
void refreshWindCache(const StepContext& ctx, const Cloth& cloth, StepState& state, int threads) {
    WindCache& W = state.wind;
    if (W.stamp.fresh(ctx.revisions, WindCache::kDeps) && W.threadRange.size() == size_t(threads)) return;
    const size_t nt = cloth.triangles.size(), n = cloth.particleCount();
    W.triangles.resize(nt);
    for (size_t i = 0; i < nt; ++i) {
        const Triangle& tri = cloth.triangles[i];
        WindTriangle& w = W.triangles[i];
        for (int k = 0; k < 3; ++k) w.p16[k] = 16u * uint32_t(tri.p[k]);
        w.areaCap = 2.f * float(tri.restArea);
        w.wMax = std::max({cloth.invMass[tri.p[0]], cloth.invMass[tri.p[1]], cloth.invMass[tri.p[2]]});
    }
    W.threadRange.assign(size_t(threads), {n, 0});
    for (int t = 0; t < threads; ++t) {
        const Chunk c = chunkOf(nt, t, threads);
        auto& [lo, hi] = W.threadRange[size_t(t)];
        for (size_t i = c.begin; i < c.end; ++i)
            for (const Index p : cloth.triangles[i].p) lo = std::min<size_t>(lo, p), hi = std::max<size_t>(hi, p + 1);
    }
    W.stamp.set(ctx.revisions);
}

struct WindKernelInput {
    const WindTriangle* tri;
    const PackedParticle* packed;
    float wind[3];   // m/s, air velocity
    float coef;      // drag coefficient / 3: each corner's share
    float dt;        // s
    bool guard;      // cap the force (see phaseWind)
};

// Triangles [begin, end) into `acc`: F = c A (n . v_rel) |n . v_rel| n on each corner's share, with
// n = cross / |cross| for the corners' cross product, so the force is (mag / |cross|) cross.
void windKernel(const WindKernelInput& in, size_t begin, size_t end, Acc4* acc) {
    // The force factor from the squared cross norm, the cross product's dot with v_rel and the
    // triangle: 0 for a degenerate triangle.
    auto factor = [&](const WindTriangle& t, float cross2, float crossDotV) {
        const float twiceArea = std::sqrt(cross2);
        // Not just > 0: a denormal area's inverse is inf, and 0 x inf is NaN (the random safe
        // parameter runs: a forward-Euler cloth torn by an 83 kg ball). Nor an inf one.
        if (!(twiceArea > 1e-20f) || !(twiceArea < 1e30f)) return 0.f;
        const float inv = 1.f / twiceArea;
        const float vn = crossDotV * inv;
        // The corners' masses come from the rest area: a sliver torn to 1e-15 m^2 whose float
        // corners cannot get closer than ~1e-8 m would catch 10^4 times its share of wind and
        // explode (soak; also with the guard off). Its area counts up to twice the rest area.
        const float area = std::min(0.5f * twiceArea, t.areaCap);
        float mag = in.coef * area * vn * std::abs(vn);
        if (in.guard) {
            const float cap = std::abs(vn) / (in.dt * std::max(t.wMax, 1e-30f));
            mag = std::clamp(mag, -cap, cap);
        }
        return mag * inv;
    };
#if defined(__SSE2__)
    const char* px = reinterpret_cast<const char*>(in.packed); // particle at 2 * offset
    char* pf = reinterpret_cast<char*>(acc);                   // accumulator at offset
    const __m128 wind = _mm_setr_ps(in.wind[0], in.wind[1], in.wind[2], 0.f);
    const __m128 third = _mm_set1_ps(1.f / 3.f);
    auto yzx = [](__m128 a) { return _mm_shuffle_ps(a, a, _MM_SHUFFLE(3, 0, 2, 1)); };
    auto sum3 = [](__m128 a) { // a.x + a.y + a.z (w is 0)
        const __m128 s = _mm_add_ps(a, _mm_movehl_ps(a, a));
        return _mm_cvtss_f32(_mm_add_ss(s, _mm_shuffle_ps(s, s, _MM_SHUFFLE(1, 1, 1, 1))));
    };
    for (size_t i = begin; i < end; ++i) {
        const WindTriangle& t = in.tri[i];
        const float* A = reinterpret_cast<const float*>(px + 2 * size_t(t.p16[0]));
        const float* B = reinterpret_cast<const float*>(px + 2 * size_t(t.p16[1]));
        const float* C = reinterpret_cast<const float*>(px + 2 * size_t(t.p16[2]));
        const __m128 a = _mm_load_ps(A);
        const __m128 e1 = _mm_sub_ps(_mm_load_ps(B), a), e2 = _mm_sub_ps(_mm_load_ps(C), a);
        // e1 x e2 = (e1.yzx * e2.zxy - e1.zxy * e2.yzx), computed as ((e1 * e2.yzx - e1.yzx * e2)).yzx.
        const __m128 cross = yzx(_mm_sub_ps(_mm_mul_ps(e1, yzx(e2)), _mm_mul_ps(yzx(e1), e2)));
        const __m128 vsum = _mm_add_ps(_mm_add_ps(_mm_load_ps(A + 4), _mm_load_ps(B + 4)), _mm_load_ps(C + 4));
        const __m128 vrel = _mm_sub_ps(wind, _mm_mul_ps(vsum, third));
        const float f = factor(t, sum3(_mm_mul_ps(cross, cross)), sum3(_mm_mul_ps(cross, vrel)));
        if (f == 0.f) continue;
        const __m128 fv = _mm_mul_ps(cross, _mm_set1_ps(f));
        for (const uint32_t off : t.p16) {
            float* to = reinterpret_cast<float*>(pf + off);
            _mm_store_ps(to, _mm_add_ps(_mm_load_ps(to), fv));
        }
    }
#else
    for (size_t i = begin; i < end; ++i) {
        const WindTriangle& t = in.tri[i];
        const PackedParticle& A = packedAt(in.packed, t.p16[0]);
        const PackedParticle& B = packedAt(in.packed, t.p16[1]);
        const PackedParticle& C = packedAt(in.packed, t.p16[2]);
        const Vec3 a(A.x[0], A.x[1], A.x[2]);
        const Vec3 cross = (Vec3(B.x[0], B.x[1], B.x[2]) - a).cross(Vec3(C.x[0], C.x[1], C.x[2]) - a);
        const Vec3 vrel = Vec3(in.wind[0], in.wind[1], in.wind[2]) -
                          Vec3(A.v[0] + B.v[0] + C.v[0], A.v[1] + B.v[1] + C.v[1], A.v[2] + B.v[2] + C.v[2]) * (1.f / 3.f);
        const float f = factor(t, cross.squaredNorm(), cross.dot(vrel));
        if (f == 0.f) continue;
        const Acc4 fv(f * cross.x(), f * cross.y(), f * cross.z(), 0.f);
        for (const uint32_t off : t.p16) accAt(acc, off) += fv;
    }
#endif
}

} // namespace

// Wind on each triangle from its normal and the relative air velocity (so a flag flutters):
//   F = c A (n . v_rel) |n . v_rel| n,   v_rel = wind - mean triangle velocity, shared by the corners,
//   A = current area, at most twice the rest area.
//
// With the stability guard on, the force on a triangle is capped so that it cannot change its
// lightest corner's normal velocity by more than the relative normal speed in one sub-step (drag
// can bring the cloth to the air's speed, not past it): explicit quadratic drag on a light cloth
// in a strong wind (rho = 0.01 kg/m^2, 30 m/s, both in the safe ranges) overshoots and explodes.
//
// The kernel reads the packed copy of positions and velocities (one cache line per particle) that
// the spring phase wrote; the reference integrators skip that phase, so here it is written for them.
void phaseWind(const StepContext& ctx, Cloth& cloth, StepState& state) {
    const WindSettings& w = ctx.settings->wind;
    Vec3 dir(w.dirX, w.dirY, w.dirZ);
    if (dir.squaredNorm() < 1e-12f) return;
    dir.normalize();
    // Gusts: two incommensurate sines, deterministic in time.
    const double ph = 2.0 * M_PI * w.gustFrequency * ctx.time;
    const float gustFactor = 1.f + w.gust * float(0.65 * std::sin(ph) + 0.35 * std::sin(2.37 * ph + 1.3));
    const Vec3 wind = dir * (w.speed * std::max(0.f, gustFactor));
    const size_t nt = cloth.triangles.size();
    const int bufferCount = int(state.threads.acc.size());
    const int threads = (bufferCount > 1 && nt >= kParallelWork) ? bufferCount : 1; // as parallelRegion splits
    refreshWindCache(ctx, cloth, state, threads);
    if (ctx.reference) {
        const size_t n = cloth.particleCount();
        for (size_t p = 0; p < n; ++p)
            state.packed[p] = packedOf(cloth.x[p], cloth.v[p]);
    }
    for (int t = 0; t < threads; ++t) { // the integrator reads each buffer over what wrote to it
        auto& r = state.threads.range[size_t(t)];
        const auto& mine = state.wind.threadRange[size_t(t)];
        r = {std::min(r[0], mine[0]), std::max(r[1], mine[1])};
    }
    const WindKernelInput in{state.wind.triangles.data(),
                             state.packed.data(),
                             {wind.x(), wind.y(), wind.z()},
                             w.dragCoefficient / 3.f,
                             ctx.dt,
                             ctx.settings->time.stabilityGuard};
    parallelRegion(nt, threads, [&](int t, int nt2) {
        const Chunk c = chunkOf(nt, t, nt2);
        windKernel(in, c.begin, c.end, state.threads.acc[t].data());
    });
}

} // namespace clothtear
