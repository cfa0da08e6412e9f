// Springs in groups of eight (spring_groups.h): finding the groups, and their kernels.
#include "spring_groups.h"
#include "uninitialized_vector.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define CLOTHTEAR_GROUPS_AVX2 1
#endif

namespace clothtear {

void ComponentArrays::resize(size_t particles, int count) {
    // Room for a stride-2 group's last load (16 floats from its first particle), rounded to a
    // 32-byte multiple so that every component starts aligned like the first.
    const size_t want = (particles + 16 + 7) / 8 * 8;
    if (want == stride && count == components) return;
    stride = want;
    components = count;
    data.assign(size_t(count) * stride, 0.f);
}

GroupKernel groupKernelInUse() {
#if defined(__SSE2__)
    GroupKernel widest = GroupKernel::Sse2;
#if CLOTHTEAR_GROUPS_AVX2
    static const bool avx2 = __builtin_cpu_supports("avx2");
    if (avx2) widest = GroupKernel::Avx2;
#endif
#else
    const GroupKernel widest = GroupKernel::None;
#endif
    const char* asked = std::getenv("CLOTHTEAR_SPRING_KERNEL");
    if (!asked) return widest;
    if (std::strcmp(asked, "generic") == 0) return GroupKernel::None;
    if (std::strcmp(asked, "sse2") == 0) return std::min(widest, GroupKernel::Sse2);
    return widest;
}

SpringOrder groupSprings(const std::vector<Spring>& springs, size_t count, size_t particles, bool makeGroups) {
    // One array of sums takes both ends of a group. Where the second ends' sixteen floats (eight
    // of stride 2) overlap the first ends' (distance below 16), the load of the second would read
    // floats the store of the first had just written, shifted, which the CPU cannot forward: those
    // groups are allowed only as chains (distance = stride: a grid's horizontal springs), whose
    // kernel adds each particle's two forces in one (ChainCarry).
    auto groupable = [](size_t d, uint32_t s) { return d == s || d >= 2 * kGroupSize; };
    SpringOrder out;
    out.order.reserve(count);
    std::vector<uint8_t> grouped(count, 0);
    // Each spring's first end (the lower index) and the distance of its ends' indices, once: the
    // sorts below read them in their own orders, and through the springs that was a cache miss each.
    // Arrays written in full before they are read are not zero-filled first (UninitializedVector).
    UninitializedVector<uint32_t> first(count), dist(count);
    for (size_t i = 0; i < count; ++i) {
        first[i] = std::min(springs[i].a, springs[i].b);
        dist[i] = std::max(springs[i].a, springs[i].b) - first[i];
    }
    auto lo = [&](size_t i) { return first[i]; };
    UninitializedVector<uint32_t> byDistance;
    struct Found {
        uint32_t first; // its springs: byDistance[first + j]
        SpringGroup group;
    };
    std::vector<Found> found;
    if (makeGroups && count >= kGroupSize && particles > 1) {
        // Sorted by the distance of the ends' indices, then by the first end (stable counting
        // sorts). Mesh order is not enough: a grid's horizontal bend-shear springs come in the order
        // of their edges, two rows interleaved, and each of them twice (two edges whose opposite
        // corners are the same two particles). So a spring's copy number among the springs with the
        // same ends comes between: distance, copy, first end, and each copy runs along the cloth.
        auto countingSort = [&](const UninitializedVector<uint32_t>& in, size_t range, auto key) {
            std::vector<uint32_t> start(range + 1, 0);
            UninitializedVector<uint32_t> out(in.size());
            for (uint32_t i : in) ++start[key(i) + 1];
            for (size_t d = 1; d <= range; ++d) start[d] += start[d - 1];
            for (uint32_t i : in) out[start[key(i)]++] = i;
            return out;
        };
        UninitializedVector<uint32_t> all(count);
        for (size_t i = 0; i < count; ++i) all[i] = uint32_t(i);
        const UninitializedVector<uint32_t> byFirst = countingSort(all, particles, lo);
        // A spring's copy number: how many springs before it (by index) have the same two ends,
        // capped at particles - 1. The springs of one first end are a particle's few: count within
        // its run of byFirst, which holds them by index.
        std::vector<uint32_t> copy(count, 0);
        uint32_t copies = 1; // the largest copy number + 1
        for (size_t k = 0; k < count;) {
            size_t end = k + 1;
            while (end < count && first[byFirst[end]] == first[byFirst[k]]) ++end;
            for (size_t i = k + 1; i < end; ++i) {
                uint32_t c = 0;
                for (size_t j = k; j < i; ++j) c += dist[byFirst[j]] == dist[byFirst[i]];
                copy[byFirst[i]] = std::min<uint32_t>(c, uint32_t(particles - 1));
                copies = std::max(copies, copy[byFirst[i]] + 1);
            }
            k = end;
        }
        // By (distance, copy), stable over byFirst: one counting sort on the pair where its range is
        // small (a grid's bend-shear springs come twice: copies = 2), else one sort per key.
        if (size_t(copies) * particles <= 8 * (particles + count))
            byDistance = countingSort(byFirst, size_t(copies) * particles,
                                      [&](uint32_t i) { return dist[i] * copies + copy[i]; });
        else
            byDistance = countingSort(countingSort(byFirst, particles, [&](uint32_t i) { return copy[i]; }), particles,
                                      [&](uint32_t i) { return dist[i]; });
        std::vector<uint32_t> start(particles + 1, 0); // first entry of each distance in byDistance
        for (uint32_t i : byDistance) ++start[dist[i] + 1];
        for (size_t d = 1; d <= particles; ++d) start[d] += start[d - 1];
        for (size_t d = 1; d < particles; ++d) {
            const size_t end = start[d + 1];
            for (size_t i = start[d]; i + kGroupSize <= end;) {
                const uint32_t a0 = lo(byDistance[i]);
                uint32_t stride = 0;
                for (uint32_t s : {1u, 2u}) {
                    if (!groupable(d, s)) continue;
                    bool run = true;
                    for (uint32_t j = 1; j < kGroupSize && run; ++j) run = lo(byDistance[i + j]) == a0 + s * j;
                    if (run) {
                        stride = s;
                        break;
                    }
                }
                if (!stride) {
                    ++i;
                    continue;
                }
                found.push_back({uint32_t(i), SpringGroup{0, a0, a0 + uint32_t(d), stride}});
                for (size_t j = 0; j < kGroupSize; ++j) grouped[byDistance[i + j]] = 1;
                i += kGroupSize;
            }
        }
    }
    // Bands of 2^kBandShift first particles, in order; in each band its groups, then its other
    // springs. A thread's chunk of the entries then touches a band of the cloth (the integrator
    // and the strain scan take the same share of the particles), and within a band the groups of
    // one distance run along it before the next: sorted by first particle alone, groups of four or
    // five distances in a row added into the same eight floats, each addition waiting on the last
    // one's store (2.5 ns per spring, no faster than kernels.h's loop). Without groups, one band
    // in mesh order: the order the cache had before the groups, to the bit.
    std::vector<Index> rest;
    rest.reserve(count);
    for (size_t i = 0; i < count; ++i)
        if (!grouped[i]) rest.push_back(Index(i));
    const size_t bands = makeGroups ? (particles >> kBandShift) + 1 : 1;
    auto bandOf = [&](uint32_t first) { return makeGroups ? size_t(first >> kBandShift) : size_t(0); };
    std::vector<uint32_t> groupAt(bands + 1, 0), restAt(bands + 1, 0);
    for (const Found& f : found) ++groupAt[bandOf(f.group.a) + 1];
    for (Index i : rest) ++restAt[bandOf(lo(i)) + 1];
    for (size_t b = 1; b <= bands; ++b) groupAt[b] += groupAt[b - 1], restAt[b] += restAt[b - 1];
    UninitializedVector<uint32_t> groupOrder(found.size());
    UninitializedVector<Index> restOrder(rest.size());
    {
        std::vector<uint32_t> g(groupAt.begin(), groupAt.end() - 1), r(restAt.begin(), restAt.end() - 1);
        for (size_t k = 0; k < found.size(); ++k) groupOrder[g[bandOf(found[k].group.a)]++] = uint32_t(k);
        for (Index i : rest) restOrder[r[bandOf(lo(i))]++] = i;
    }
    out.groups.reserve(found.size());
    for (size_t b = 0; b < bands; ++b) {
        SpringBand band;
        band.groupsBegin = uint32_t(out.groups.size());
        for (uint32_t k = groupAt[b]; k < groupAt[b + 1]; ++k) {
            const Found& f = found[groupOrder[k]];
            out.groups.push_back(f.group);
            out.groups.back().entry = uint32_t(out.order.size());
            for (size_t j = 0; j < kGroupSize; ++j) out.order.push_back(byDistance[f.first + j]);
        }
        band.groupsEnd = uint32_t(out.groups.size());
        // The other springs in mesh order, permuted within blocks of 64: entry 8q + j holds spring
        // 8j + q of the block, so the springs of kernels.h's groups of four come from places 8
        // springs apart. Springs next to each other in mesh order share particles, and a group that
        // adds into the same accumulator several times waits on its own stores (5.2 ns per spring
        // in mesh order, 3.3 interleaved, groups of four).
        band.restBegin = uint32_t(out.order.size());
        const size_t n = restAt[b + 1] - restAt[b];
        const Index* mine = restOrder.data() + restAt[b];
        constexpr size_t kBlock = 64, kWays = 8, kLane = kBlock / kWays;
        for (size_t e = 0; e < n; ++e) {
            const size_t base = e - e % kBlock, q = e % kBlock;
            const size_t i = base + kBlock <= n ? base + (q % kWays) * kLane + q / kWays : e;
            out.order.push_back(mine[i]);
        }
        band.restEnd = uint32_t(out.order.size());
        if (band.groupsEnd > band.groupsBegin || band.restEnd > band.restBegin) out.bands.push_back(band);
    }
    return out;
}

namespace {

// The arrays of one group kernel: the particles' six components in, the forces' three out.
struct GroupArrays {
    const float* in[6];
    float* out[3];
};

// A chain (distance = stride, see groupSprings) adds f_j into particle a + s j and takes it from
// a + s (j + 1): each particle's net is f_j - f_(j-1), added once. f_(-1) is the previous group's
// last force when that group ended where this one starts (`carry`), else 0; the last force goes to
// the next group the same way, or alone into a + 8 s (flush).
struct ChainCarry {
    bool pending = false;
    uint32_t at = 0, stride = 0; // the particle it goes into, and the chain's stride
    float f[3] = {};
    // The carry for a chain group starting at a: its forces, or zeros after flushing a carry
    // that goes elsewhere.
    void take(uint32_t a, uint32_t s, float* out0, float* out1, float* out2, float in[3]) {
        if (pending && at == a && stride == s) {
            for (int c = 0; c < 3; ++c) in[c] = f[c];
        } else {
            flush(out0, out1, out2);
            in[0] = in[1] = in[2] = 0.f;
        }
        pending = false;
    }
    void flush(float* out0, float* out1, float* out2) {
        if (!pending) return;
        out0[at] -= f[0];
        out1[at] -= f[1];
        out2[at] -= f[2];
        pending = false;
    }
};

#if defined(__SSE2__)
// Four lanes of a component from particles p, p + s, p + 2 s, p + 3 s (s = 1 or 2).
inline __m128 load4(const float* c, uint32_t p, uint32_t s) {
    if (s == 1) return _mm_loadu_ps(c + p);
    return _mm_shuffle_ps(_mm_loadu_ps(c + p), _mm_loadu_ps(c + p + 4), _MM_SHUFFLE(2, 0, 2, 0));
}

// to[p + s j] += f[j] (j = 0..3; minus: -=); with s = 2 the floats between get + 0.
inline void add4(float* to, uint32_t p, uint32_t s, __m128 f, bool minus) {
    auto rmw = [&](float* at, __m128 v) {
        const __m128 old = _mm_loadu_ps(at);
        _mm_storeu_ps(at, minus ? _mm_sub_ps(old, v) : _mm_add_ps(old, v));
    };
    if (s == 1) return rmw(to + p, f);
    const __m128 zero = _mm_setzero_ps();
    rmw(to + p, _mm_unpacklo_ps(f, zero));
    rmw(to + p + 4, _mm_unpackhi_ps(f, zero));
}

// The forces along the springs of four lanes, f (x, y, z) = (k (L - L0) + kd (v_b - v_a).n) n, or
// the one term T asks for.
template <SpringTerms T>
inline void forces4(const GroupArrays& A, uint32_t a, uint32_t b, uint32_t s, const float* rest, const float* k,
                    const float* kd, size_t e, __m128 out[3]) {
    const __m128 one = _mm_set1_ps(1.f);
    __m128 d[3], dv[3] = {};
    for (int i = 0; i < 3; ++i) {
        d[i] = _mm_sub_ps(load4(A.in[i], b, s), load4(A.in[i], a, s));
        if constexpr (T != SpringTerms::Elastic) dv[i] = _mm_sub_ps(load4(A.in[3 + i], b, s), load4(A.in[3 + i], a, s));
    }
    const __m128 len2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(d[0], d[0]), _mm_mul_ps(d[1], d[1])), _mm_mul_ps(d[2], d[2]));
    const __m128 len = _mm_sqrt_ps(len2);
    const __m128 valid = _mm_cmpgt_ps(len, _mm_set1_ps(1e-12f));
    const __m128 inv = _mm_div_ps(one, _mm_or_ps(_mm_andnot_ps(valid, one), _mm_and_ps(valid, len)));
    __m128 along = _mm_setzero_ps(); // the force's size times L
    if constexpr (T != SpringTerms::Damping)
        along = _mm_mul_ps(_mm_loadu_ps(k + e), _mm_sub_ps(len, _mm_loadu_ps(rest + e)));
    if constexpr (T != SpringTerms::Elastic) {
        const __m128 dvd =
            _mm_add_ps(_mm_add_ps(_mm_mul_ps(dv[0], d[0]), _mm_mul_ps(dv[1], d[1])), _mm_mul_ps(dv[2], d[2]));
        const __m128 damp = _mm_mul_ps(_mm_loadu_ps(kd + e), _mm_mul_ps(dvd, inv));
        along = T == SpringTerms::Both ? _mm_add_ps(along, damp) : damp;
    }
    const __m128 f = _mm_and_ps(valid, _mm_mul_ps(along, inv));
    for (int i = 0; i < 3; ++i) out[i] = _mm_mul_ps(f, d[i]);
}

template <SpringTerms T>
void groupsSse2(const SpringGroup* groups, size_t g0, size_t g1, const float* rest, const float* k, const float* kd,
                const GroupArrays& A) {
    ChainCarry carry;
    for (size_t g = g0; g < g1; ++g) {
        const SpringGroup& G = groups[g];
        const uint32_t s = G.stride;
        __m128 lo[3], hi[3]; // springs 0-3 and 4-7
        forces4<T>(A, G.a, G.b, s, rest, k, kd, G.entry, lo);
        forces4<T>(A, G.a + 4 * s, G.b + 4 * s, s, rest, k, kd, G.entry + 4, hi);
        if (G.b - G.a != s) {
            carry.flush(A.out[0], A.out[1], A.out[2]);
            for (int i = 0; i < 3; ++i) {
                add4(A.out[i], G.a, s, lo[i], false);
                add4(A.out[i], G.a + 4 * s, s, hi[i], false);
                add4(A.out[i], G.b, s, lo[i], true);
                add4(A.out[i], G.b + 4 * s, s, hi[i], true);
            }
            continue;
        }
        float in[3];
        carry.take(G.a, s, A.out[0], A.out[1], A.out[2], in);
        for (int i = 0; i < 3; ++i) {
            // (f_-1, f0, f1, f2) and (f3, f4, f5, f6): the forces one lane later.
            const __m128 prevLo = _mm_move_ss(_mm_shuffle_ps(lo[i], lo[i], _MM_SHUFFLE(2, 1, 0, 0)), _mm_set_ss(in[i]));
            const __m128 prevHi = _mm_move_ss(_mm_shuffle_ps(hi[i], hi[i], _MM_SHUFFLE(2, 1, 0, 0)),
                                              _mm_shuffle_ps(lo[i], lo[i], _MM_SHUFFLE(3, 3, 3, 3)));
            add4(A.out[i], G.a, s, _mm_sub_ps(lo[i], prevLo), false);
            add4(A.out[i], G.a + 4 * s, s, _mm_sub_ps(hi[i], prevHi), false);
            carry.f[i] = _mm_cvtss_f32(_mm_shuffle_ps(hi[i], hi[i], _MM_SHUFFLE(3, 3, 3, 3)));
        }
        carry.pending = true;
        carry.at = G.a + kGroupSize * s;
        carry.stride = s;
    }
    carry.flush(A.out[0], A.out[1], A.out[2]);
}
#endif

#if CLOTHTEAR_GROUPS_AVX2
// Eight lanes of a component from particles p + s j (s = 1 or 2).
__attribute__((target("avx2"))) inline __m256 load8(const float* c, uint32_t p, uint32_t s) {
    if (s == 1) return _mm256_loadu_ps(c + p);
    // (e0 e2 e8 e10 | e4 e6 e12 e14), then the 64-bit pairs put in order.
    const __m256 evens = _mm256_shuffle_ps(_mm256_loadu_ps(c + p), _mm256_loadu_ps(c + p + 8), _MM_SHUFFLE(2, 0, 2, 0));
    return _mm256_castpd_ps(_mm256_permute4x64_pd(_mm256_castps_pd(evens), _MM_SHUFFLE(3, 1, 2, 0)));
}

__attribute__((target("avx2"))) inline void rmw8(float* at, __m256 v, bool minus) {
    const __m256 old = _mm256_loadu_ps(at);
    _mm256_storeu_ps(at, minus ? _mm256_sub_ps(old, v) : _mm256_add_ps(old, v));
}

// to[p + s j] += f[j] (j = 0..7; minus: -=); with s = 2 the floats between get + 0.
__attribute__((target("avx2"))) inline void add8(float* to, uint32_t p, uint32_t s, __m256 f, bool minus) {
    if (s == 1) return rmw8(to + p, f, minus);
    const __m256 zero = _mm256_setzero_ps();
    const __m256 lo = _mm256_unpacklo_ps(f, zero), hi = _mm256_unpackhi_ps(f, zero); // (f0 0 f1 0 | f4 0 f5 0), ...
    rmw8(to + p, _mm256_permute2f128_ps(lo, hi, 0x20), minus);
    rmw8(to + p + 8, _mm256_permute2f128_ps(lo, hi, 0x31), minus);
}

// The operations of groupsSse2 lane by lane, eight springs at once.
template <SpringTerms T>
__attribute__((target("avx2"))) void groupsAvx2(const SpringGroup* groups, size_t g0, size_t g1, const float* rest,
                                                const float* k, const float* kd, const GroupArrays& A) {
    const __m256 one = _mm256_set1_ps(1.f), tiny = _mm256_set1_ps(1e-12f);
    const __m256i laterLane = _mm256_setr_epi32(0, 0, 1, 2, 3, 4, 5, 6);
    ChainCarry carry;
    for (size_t g = g0; g < g1; ++g) {
        const SpringGroup& G = groups[g];
        const uint32_t a = G.a, b = G.b, s = G.stride;
        const size_t e = G.entry;
        const __m256 dx = _mm256_sub_ps(load8(A.in[0], b, s), load8(A.in[0], a, s));
        const __m256 dy = _mm256_sub_ps(load8(A.in[1], b, s), load8(A.in[1], a, s));
        const __m256 dz = _mm256_sub_ps(load8(A.in[2], b, s), load8(A.in[2], a, s));
        // The velocities' loads before the square root, as the kernel had them before the terms
        // were split: later, the compiler spilled registers round them (3 % more instructions).
        __m256 dvx = _mm256_setzero_ps(), dvy = dvx, dvz = dvx;
        if constexpr (T != SpringTerms::Elastic) {
            dvx = _mm256_sub_ps(load8(A.in[3], b, s), load8(A.in[3], a, s));
            dvy = _mm256_sub_ps(load8(A.in[4], b, s), load8(A.in[4], a, s));
            dvz = _mm256_sub_ps(load8(A.in[5], b, s), load8(A.in[5], a, s));
        }
        const __m256 len2 = _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(dx, dx), _mm256_mul_ps(dy, dy)), _mm256_mul_ps(dz, dz));
        const __m256 len = _mm256_sqrt_ps(len2);
        const __m256 valid = _mm256_cmp_ps(len, tiny, _CMP_GT_OQ);
        const __m256 inv = _mm256_div_ps(one, _mm256_or_ps(_mm256_andnot_ps(valid, one), _mm256_and_ps(valid, len)));
        __m256 along = _mm256_setzero_ps(); // the force's size times L
        if constexpr (T != SpringTerms::Damping)
            along = _mm256_mul_ps(_mm256_loadu_ps(k + e), _mm256_sub_ps(len, _mm256_loadu_ps(rest + e)));
        if constexpr (T != SpringTerms::Elastic) {
            const __m256 dvd =
                _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(dvx, dx), _mm256_mul_ps(dvy, dy)), _mm256_mul_ps(dvz, dz));
            const __m256 damp = _mm256_mul_ps(_mm256_loadu_ps(kd + e), _mm256_mul_ps(dvd, inv));
            along = T == SpringTerms::Both ? _mm256_add_ps(along, damp) : damp;
        }
        const __m256 f = _mm256_and_ps(valid, _mm256_mul_ps(along, inv));
        const __m256 fv[3] = {_mm256_mul_ps(f, dx), _mm256_mul_ps(f, dy), _mm256_mul_ps(f, dz)};
        if (b - a != s) {
            carry.flush(A.out[0], A.out[1], A.out[2]);
            for (int i = 0; i < 3; ++i) {
                add8(A.out[i], a, s, fv[i], false);
                add8(A.out[i], b, s, fv[i], true);
            }
            continue;
        }
        float in[3];
        carry.take(a, s, A.out[0], A.out[1], A.out[2], in);
        for (int i = 0; i < 3; ++i) {
            // (f_-1, f0, ..., f6): the forces one lane later.
            const __m256 prev = _mm256_blend_ps(_mm256_permutevar8x32_ps(fv[i], laterLane), _mm256_set1_ps(in[i]), 0x01);
            add8(A.out[i], a, s, _mm256_sub_ps(fv[i], prev), false);
            carry.f[i] = _mm_cvtss_f32(_mm_shuffle_ps(_mm256_extractf128_ps(fv[i], 1), _mm256_extractf128_ps(fv[i], 1),
                                                      _MM_SHUFFLE(3, 3, 3, 3)));
        }
        carry.pending = true;
        carry.at = a + kGroupSize * s;
        carry.stride = s;
    }
    carry.flush(A.out[0], A.out[1], A.out[2]);
}
#endif

// Without SSE2: springForceScalar's formula on each entry.
template <SpringTerms T>
void groupsScalar(const SpringGroup* groups, size_t g0, size_t g1, const float* rest, const float* k, const float* kd,
                  const GroupArrays& A) {
    const float* const* c = A.in;
    for (size_t g = g0; g < g1; ++g) {
        const SpringGroup& G = groups[g];
        for (uint32_t j = 0; j < kGroupSize; ++j) {
            const uint32_t a = G.a + G.stride * j, b = G.b + G.stride * j;
            const size_t e = G.entry + j;
            const float dx = c[0][b] - c[0][a], dy = c[1][b] - c[1][a], dz = c[2][b] - c[2][a];
            const float len = std::sqrt(dx * dx + dy * dy + dz * dz);
            if (!(len > 1e-12f)) continue;
            const float inv = 1.f / len;
            float along = 0.f;
            if constexpr (T != SpringTerms::Damping) along = k[e] * (len - rest[e]);
            if constexpr (T != SpringTerms::Elastic) {
                const float dvd = ((c[3][b] - c[3][a]) * dx + (c[4][b] - c[4][a]) * dy + (c[5][b] - c[5][a]) * dz) * inv;
                along = T == SpringTerms::Both ? along + kd[e] * dvd : kd[e] * dvd;
            }
            const float f = along * inv;
            const float fv[3] = {f * dx, f * dy, f * dz};
            for (int i = 0; i < 3; ++i) {
                A.out[i][a] += fv[i];
                A.out[i][b] -= fv[i];
            }
        }
    }
}

template <SpringTerms T>
void groupsWith(GroupKernel kernel, const SpringGroup* groups, size_t g0, size_t g1, const float* rest, const float* k,
                const float* kd, const GroupArrays& A) {
    switch (kernel) {
#if CLOTHTEAR_GROUPS_AVX2
    case GroupKernel::Avx2: groupsAvx2<T>(groups, g0, g1, rest, k, kd, A); return;
#endif
#if defined(__SSE2__)
    case GroupKernel::Sse2: groupsSse2<T>(groups, g0, g1, rest, k, kd, A); return;
#endif
    default: groupsScalar<T>(groups, g0, g1, rest, k, kd, A); return;
    }
}

} // namespace

void springForcesGrouped(GroupKernel kernel, SpringTerms terms, const SpringGroup* groups, size_t g0, size_t g1,
                         const float* rest, const float* k, const float* kd, const ComponentArrays& particles,
                         ComponentArrays& forces) {
    GroupArrays A;
    for (int i = 0; i < 6; ++i) A.in[i] = particles.component(i);
    for (int i = 0; i < 3; ++i) A.out[i] = forces.component(i);
    switch (terms) {
    case SpringTerms::Both: groupsWith<SpringTerms::Both>(kernel, groups, g0, g1, rest, k, kd, A); return;
    case SpringTerms::Elastic: groupsWith<SpringTerms::Elastic>(kernel, groups, g0, g1, rest, k, kd, A); return;
    case SpringTerms::Damping: groupsWith<SpringTerms::Damping>(kernel, groups, g0, g1, rest, k, kd, A); return;
    }
}

} // namespace clothtear
