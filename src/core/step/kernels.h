// The inner loops of the step's spring phase and strain scan, over flat arrays (springs.cpp,
// limit.cpp).
//
// Layout. Particles are read from a packed copy, 32 bytes each: position (x, y, z, 0) and velocity
// (x, y, z, 0), aligned, so one particle is two aligned loads in one cache line. Forces go to
// 16-byte accumulators (x, y, z, unused). Springs store their ends as byte offsets (16 * particle):
// the packed copy is at 2 * offset, the accumulator at offset, so no index arithmetic is left in the
// loop. With SSE2 (every x86-64) four springs are done at once: their square roots and divisions
// share one instruction each, which is what bounds a scalar loop (a square root and a division per
// spring). Other targets use the scalar loop, with the same formula.
#pragma once
#include "step_state.h" // PackedParticle

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace clothtear {

// Force accumulator of one particle: xyz, w unused.
using Acc4 = Eigen::Vector4f;

// Springs as the kernels read them: one array per field, ends as byte offsets (16 * particle).
struct SpringArrays {
    const uint32_t* a16;
    const uint32_t* b16;
    const float* rest; // m
    const float* k;    // N/m, after the stability guard
    const float* kd;   // N s/m, after the stability guard
};

// The spring cache's arrays as the kernels read them.
inline SpringArrays springArraysOf(const SpringCache& S) {
    return {S.a16.data(), S.b16.data(), S.rest.data(), S.k.data(), S.kd.data()};
}

inline const PackedParticle& packedAt(const PackedParticle* xv, uint32_t off16) {
    return xv[off16 >> 4];
}
inline Acc4& accAt(Acc4* acc, uint32_t off16) { return acc[off16 >> 4]; }

// Hooke + damping along spring i, on its first end (the second gets the opposite):
//   f = (k (L - L0) + kd (v_b - v_a).n) n,   n = (x_b - x_a) / L;   nothing when L is 0.
// T: both terms, or one of them (SpringTerms, spring_groups.h).
template <SpringTerms T = SpringTerms::Both>
inline void springForceScalar(const SpringArrays& s, size_t i, const PackedParticle* xv, Acc4* acc) {
    const PackedParticle& A = packedAt(xv, s.a16[i]);
    const PackedParticle& B = packedAt(xv, s.b16[i]);
    const float dx = B.x[0] - A.x[0], dy = B.x[1] - A.x[1], dz = B.x[2] - A.x[2];
    const float len = std::sqrt(dx * dx + dy * dy + dz * dz);
    if (!(len > 1e-12f)) return;
    const float inv = 1.f / len;
    float along = 0.f; // the force's size times L
    if constexpr (T != SpringTerms::Damping) along = s.k[i] * (len - s.rest[i]);
    if constexpr (T != SpringTerms::Elastic) {
        const float dvd = ((B.v[0] - A.v[0]) * dx + (B.v[1] - A.v[1]) * dy + (B.v[2] - A.v[2]) * dz) * inv;
        along = T == SpringTerms::Both ? along + s.kd[i] * dvd : s.kd[i] * dvd;
    }
    const float f = along * inv;
    const Acc4 fv(f * dx, f * dy, f * dz, 0.f);
    accAt(acc, s.a16[i]) += fv;
    accAt(acc, s.b16[i]) -= fv;
}

// Springs [begin, end) into `acc`; T: both terms or one of them.
template <SpringTerms T = SpringTerms::Both>
inline void springForces(const SpringArrays& s, size_t begin, size_t end, const PackedParticle* xv, Acc4* acc) {
    size_t i = begin;
#if defined(__SSE2__)
    const uint32_t* __restrict a16 = s.a16;
    const uint32_t* __restrict b16 = s.b16;
    const float* __restrict rest = s.rest;
    const float* __restrict k = s.k;
    const float* __restrict kd = s.kd;
    const char* __restrict px = reinterpret_cast<const char*>(xv); // particle at 2 * offset
    char* __restrict pf = reinterpret_cast<char*>(acc);            // accumulator at offset
    const __m128 tiny = _mm_set1_ps(1e-12f);
    const __m128 one = _mm_set1_ps(1.f);
    for (; i + 4 <= end; i += 4) {
        constexpr bool velocities = T != SpringTerms::Elastic;
        __m128 d[4], dv[4] = {};
        uint32_t ia[4], ib[4];
        for (int j = 0; j < 4; ++j) {
            ia[j] = a16[i + j];
            ib[j] = b16[i + j];
            const float* A = reinterpret_cast<const float*>(px + 2 * size_t(ia[j]));
            const float* B = reinterpret_cast<const float*>(px + 2 * size_t(ib[j]));
            d[j] = _mm_sub_ps(_mm_load_ps(B), _mm_load_ps(A));
            if constexpr (velocities) dv[j] = _mm_sub_ps(_mm_load_ps(B + 4), _mm_load_ps(A + 4));
        }
        const __m128 dj[4] = {d[0], d[1], d[2], d[3]}; // one spring per vector, for the forces
        // Four springs side by side: dx = (d0.x, d1.x, d2.x, d3.x), ...
        _MM_TRANSPOSE4_PS(d[0], d[1], d[2], d[3]);
        if constexpr (velocities) _MM_TRANSPOSE4_PS(dv[0], dv[1], dv[2], dv[3]);
        const __m128 len2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(d[0], d[0]), _mm_mul_ps(d[1], d[1])), _mm_mul_ps(d[2], d[2]));
        const __m128 len = _mm_sqrt_ps(len2);
        const __m128 valid = _mm_cmpgt_ps(len, tiny);
        const __m128 inv = _mm_div_ps(one, _mm_or_ps(_mm_andnot_ps(valid, one), _mm_and_ps(valid, len)));
        __m128 along = _mm_setzero_ps(); // the force's size times L
        if constexpr (T != SpringTerms::Damping)
            along = _mm_mul_ps(_mm_loadu_ps(k + i), _mm_sub_ps(len, _mm_loadu_ps(rest + i)));
        if constexpr (velocities) {
            const __m128 dvd =
                _mm_add_ps(_mm_add_ps(_mm_mul_ps(dv[0], d[0]), _mm_mul_ps(dv[1], d[1])), _mm_mul_ps(dv[2], d[2]));
            const __m128 damp = _mm_mul_ps(_mm_loadu_ps(kd + i), _mm_mul_ps(dvd, inv));
            along = T == SpringTerms::Both ? _mm_add_ps(along, damp) : damp;
        }
        const __m128 f = _mm_and_ps(valid, _mm_mul_ps(along, inv));
        const __m128 fs[4] = {_mm_mul_ps(_mm_shuffle_ps(f, f, 0x00), dj[0]), _mm_mul_ps(_mm_shuffle_ps(f, f, 0x55), dj[1]),
                              _mm_mul_ps(_mm_shuffle_ps(f, f, 0xAA), dj[2]), _mm_mul_ps(_mm_shuffle_ps(f, f, 0xFF), dj[3])};
        for (int j = 0; j < 4; ++j) {
            float* fa = reinterpret_cast<float*>(pf + ia[j]);
            float* fb = reinterpret_cast<float*>(pf + ib[j]);
            _mm_store_ps(fa, _mm_add_ps(_mm_load_ps(fa), fs[j]));
            _mm_store_ps(fb, _mm_sub_ps(_mm_load_ps(fb), fs[j]));
        }
    }
#endif
    for (; i < end; ++i) springForceScalar<T>(s, i, xv, acc);
}

// Calls flagged(i, len2) for every spring i of [begin, end) whose squared length len2 is above
// (rest_i * ratio)^2: the strain scan of the limit phase, with no square root. Four springs at a
// time with SSE2; most groups of four are all below and cost one compare. Returns whether any spring
// is above (rest_i * watchRatio)^2 (a second, lower bar that calls nothing: the limit asks whether a
// tether can pull at all, see limit.cpp).
template <class Flagged>
inline bool scanSprings(const SpringArrays& s, size_t begin, size_t end, float ratio, float watchRatio,
                        const PackedParticle* xv, Flagged&& flagged) {
    size_t i = begin;
    const float ratio2 = ratio * ratio, watch2 = watchRatio * watchRatio;
    bool watched = false;
#if defined(__SSE2__)
    const char* px = reinterpret_cast<const char*>(xv);
    const __m128 r2 = _mm_set1_ps(ratio2), w2 = _mm_set1_ps(watch2);
    __m128 anyWatched = _mm_setzero_ps();
    for (; i + 4 <= end; i += 4) {
        __m128 d[4];
        for (int j = 0; j < 4; ++j) {
            const float* A = reinterpret_cast<const float*>(px + 2 * size_t(s.a16[i + j]));
            const float* B = reinterpret_cast<const float*>(px + 2 * size_t(s.b16[i + j]));
            d[j] = _mm_sub_ps(_mm_load_ps(B), _mm_load_ps(A));
            d[j] = _mm_mul_ps(d[j], d[j]);
        }
        _MM_TRANSPOSE4_PS(d[0], d[1], d[2], d[3]);
        const __m128 len2 = _mm_add_ps(_mm_add_ps(d[0], d[1]), d[2]);
        const __m128 r = _mm_loadu_ps(s.rest + i);
        const __m128 rr = _mm_mul_ps(r, r);
        anyWatched = _mm_or_ps(anyWatched, _mm_cmpgt_ps(len2, _mm_mul_ps(rr, w2)));
        const int mask = _mm_movemask_ps(_mm_cmpgt_ps(len2, _mm_mul_ps(rr, r2)));
        if (mask == 0) continue;
        alignas(16) float l2[4];
        _mm_store_ps(l2, len2);
        for (int j = 0; j < 4; ++j)
            if (mask & (1 << j)) flagged(i + j, l2[j]);
    }
    watched = _mm_movemask_ps(anyWatched) != 0;
#endif
    for (; i < end; ++i) {
        const PackedParticle& A = packedAt(xv, s.a16[i]);
        const PackedParticle& B = packedAt(xv, s.b16[i]);
        const float dx = B.x[0] - A.x[0], dy = B.x[1] - A.x[1], dz = B.x[2] - A.x[2];
        const float len2 = dx * dx + dy * dy + dz * dz;
        watched |= len2 > s.rest[i] * s.rest[i] * watch2;
        if (len2 > s.rest[i] * s.rest[i] * ratio2) flagged(i, len2);
    }
    return watched;
}

} // namespace clothtear

namespace clothtear {

// Tethers of particles [begin, end) (see tethers.h): a particle p with anchor a = anchor[p] (kNone:
// no tether, also for pinned particles) must stay within maxRatio * length[p] of it; one farther
// away moves back onto that sphere. Positions and velocities are read from `packed` (x and v after
// integration; anchors are pinned, so nothing moves them here) and the moved particles are written
// to x and v. Particles with cut[p] set are skipped (cut may be null). Inelastic velocity fix as in
// the Jacobi passes (addCorrection in limit_kernels.h): with the move delta = s d (d = x_p - x_a,
// s = L / |d| - 1 < 0), the velocity away from the anchor, v.d > 0, is cancelled up to |delta| / dt:
//   v += delta * min(1 / dt, (v.d) / (-s |d|^2)).
// Without velocityFix (Verlet, whose velocity is the position change over dt) the move
// is all velocity: v += delta / dt. The moved particles are appended to `moved`, in order.
inline void tetherKernel(size_t begin, size_t end, const Index* anchor, const float* length, const uint8_t* cut,
                         float maxRatio, float dt, bool velocityFix, const PackedParticle* packed, Vec3* x, Vec3* v,
                         std::vector<Index>& moved) {
    auto one = [&](size_t p) {
        const Index a = anchor[p];
        if (a == kNone || (cut && cut[p])) return;
        const PackedParticle& P = packed[p];
        const PackedParticle& A = packed[a];
        const float dx = P.x[0] - A.x[0], dy = P.x[1] - A.x[1], dz = P.x[2] - A.x[2];
        const float len2 = dx * dx + dy * dy + dz * dz, L = maxRatio * length[p];
        if (len2 <= L * L) return;
        const float s = L / std::sqrt(len2) - 1.f;
        // len2 just above L^2 can round to s = 0: nothing to move, and the velocity fix below would
        // divide by -0 and multiply the zero move by -inf (NaN; a ball scene at 96 a side).
        if (!(s < 0.f)) return;
        const Vec3 delta(dx * s, dy * s, dz * s);
        x[p] = Vec3(P.x[0], P.x[1], P.x[2]) + delta;
        moved.push_back(Index(p));
        if (!velocityFix) {
            v[p] = Vec3(P.v[0], P.v[1], P.v[2]) + delta * (1.f / dt);
            return;
        }
        const float vd = P.v[0] * dx + P.v[1] * dy + P.v[2] * dz;
        if (vd > 0.f) v[p] = Vec3(P.v[0], P.v[1], P.v[2]) + delta * std::min(1.f / dt, vd / (-s * len2));
    };
    size_t p = begin;
#if defined(__SSE2__)
    const __m128 ratio = _mm_set1_ps(maxRatio), invDt = _mm_set1_ps(1.f / dt), ones = _mm_set1_ps(1.f);
    const __m128 zero = _mm_setzero_ps();
    const __m128i none = _mm_set1_epi32(int(kNone));
    // Four xyz vectors (w ignored) to twelve consecutive floats: x0 y0 z0 x1 | y1 z1 x2 y2 | z2 x3 y3 z3.
    auto store4x3 = [](float* to, const __m128 r[4]) {
        const __m128 a = _mm_shuffle_ps(r[0], _mm_shuffle_ps(r[0], r[1], _MM_SHUFFLE(0, 0, 2, 2)), _MM_SHUFFLE(2, 0, 1, 0));
        const __m128 b = _mm_shuffle_ps(r[1], r[2], _MM_SHUFFLE(1, 0, 2, 1));
        const __m128 c = _mm_shuffle_ps(_mm_shuffle_ps(r[2], r[3], _MM_SHUFFLE(0, 0, 2, 2)), r[3], _MM_SHUFFLE(2, 1, 2, 0));
        _mm_storeu_ps(to, a);
        _mm_storeu_ps(to + 4, b);
        _mm_storeu_ps(to + 8, c);
    };
    auto store3 = [](Vec3& to, __m128 from) {
        _mm_storel_pi(reinterpret_cast<__m64*>(to.data()), from);
        _mm_store_ss(to.data() + 2, _mm_movehl_ps(from, from));
    };
    for (; p + 4 <= end; p += 4) {
        const __m128i a4 = _mm_loadu_si128(reinterpret_cast<const __m128i*>(anchor + p));
        int usable = ~_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(a4, none))) & 15;
        if (cut)
            for (int j = 0; j < 4; ++j)
                if (cut[p + j]) usable &= ~(1 << j);
        if (!usable) continue;
        __m128 d[4], dt4[4], vv[4], xp[4];
        for (int j = 0; j < 4; ++j) {
            const Index a = (usable >> j & 1) ? anchor[p + j] : Index(p + j);
            xp[j] = _mm_load_ps(packed[p + j].x);
            vv[j] = _mm_load_ps(packed[p + j].v);
            d[j] = dt4[j] = _mm_sub_ps(xp[j], _mm_load_ps(packed[a].x));
        }
        __m128 vt[4] = {vv[0], vv[1], vv[2], vv[3]};
        _MM_TRANSPOSE4_PS(dt4[0], dt4[1], dt4[2], dt4[3]);
        const __m128 len2 =
            _mm_add_ps(_mm_add_ps(_mm_mul_ps(dt4[0], dt4[0]), _mm_mul_ps(dt4[1], dt4[1])), _mm_mul_ps(dt4[2], dt4[2]));
        const __m128 L = _mm_mul_ps(ratio, _mm_loadu_ps(length + p));
        const int over = _mm_movemask_ps(_mm_cmpgt_ps(len2, _mm_mul_ps(L, L))) & usable;
        if (!over) continue;
        // Lanes not over: |d| replaced by 1, their results unused.
        const __m128 pos = _mm_cmpgt_ps(len2, zero);
        const __m128 safe = _mm_or_ps(_mm_and_ps(pos, len2), _mm_andnot_ps(pos, ones));
        const __m128 s = _mm_sub_ps(_mm_div_ps(L, _mm_sqrt_ps(safe)), ones);
        __m128 coef = invDt; // Verlet: v += delta / dt
        if (velocityFix) {
            _MM_TRANSPOSE4_PS(vt[0], vt[1], vt[2], vt[3]);
            const __m128 vd =
                _mm_add_ps(_mm_add_ps(_mm_mul_ps(vt[0], dt4[0]), _mm_mul_ps(vt[1], dt4[1])), _mm_mul_ps(vt[2], dt4[2]));
            const __m128 den = _mm_mul_ps(_mm_sub_ps(zero, s), safe);
            const __m128 denPos = _mm_cmpgt_ps(den, zero);
            const __m128 denSafe = _mm_or_ps(_mm_and_ps(denPos, den), _mm_andnot_ps(denPos, ones));
            coef = _mm_and_ps(_mm_min_ps(invDt, _mm_div_ps(vd, denSafe)), _mm_cmpgt_ps(vd, zero));
        }
        const __m128 sj[4] = {_mm_shuffle_ps(s, s, 0x00), _mm_shuffle_ps(s, s, 0x55), _mm_shuffle_ps(s, s, 0xAA),
                              _mm_shuffle_ps(s, s, 0xFF)};
        const __m128 cj[4] = {_mm_shuffle_ps(coef, coef, 0x00), _mm_shuffle_ps(coef, coef, 0x55),
                              _mm_shuffle_ps(coef, coef, 0xAA), _mm_shuffle_ps(coef, coef, 0xFF)};
        if (over == 15) {
            // All four move (the common case at rest): three 16-byte stores per array for the four
            // consecutive Vec3s instead of four 12-byte ones.
            __m128 xn[4], vn[4];
            for (int j = 0; j < 4; ++j) {
                const __m128 delta = _mm_mul_ps(d[j], sj[j]);
                xn[j] = _mm_add_ps(xp[j], delta);
                vn[j] = _mm_add_ps(vv[j], _mm_mul_ps(delta, cj[j])); // coef 0: the velocity it read
            }
            store4x3(x[p].data(), xn);
            store4x3(v[p].data(), vn);
            for (int j = 0; j < 4; ++j) moved.push_back(Index(p + j));
            continue;
        }
        for (int j = 0; j < 4; ++j) {
            if (!(over >> j & 1)) continue;
            const __m128 delta = _mm_mul_ps(d[j], sj[j]);
            store3(x[p + j], _mm_add_ps(xp[j], delta));
            // With coef 0 this writes back the velocity it read (packed v is v after integration).
            store3(v[p + j], _mm_add_ps(vv[j], _mm_mul_ps(delta, cj[j])));
            moved.push_back(Index(p + j));
        }
    }
#endif
    for (; p < end; ++p) one(p);
}

} // namespace clothtear
