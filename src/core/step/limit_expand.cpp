// The limit's listing after a pass, eight springs at a time (limit_expand.h).
#include "limit_expand.h"

#include <bit>
#include <cstdlib>
#include <cstring>
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define CLOTHTEAR_LISTING_AVX2 1
#endif

namespace clothtear {

static_assert(sizeof(Vec3) == 3 * sizeof(float), "the kernel gathers x, y and z of particle q at 3q, 3q + 1, 3q + 2");

bool listingAvx2Available() {
#if CLOTHTEAR_LISTING_AVX2
    static const bool cpu = __builtin_cpu_supports("avx2");
    const char* asked = std::getenv("CLOTHTEAR_LISTING_KERNEL");
    return cpu && !(asked && std::strcmp(asked, "scalar") == 0);
#else
    return false;
#endif
}

#if CLOTHTEAR_LISTING_AVX2
namespace {

// For each mask of eight lanes, the lanes set, in order, then zeros: a permutation that packs the
// taken lanes to the front.
struct PackTable {
    alignas(32) uint32_t lanes[256][8] = {};
    PackTable() {
        for (uint32_t m = 0; m < 256; ++m)
            for (uint32_t b = 0, j = 0; b < 8; ++b)
                if (m >> b & 1u) lanes[m][j++] = b;
    }
};
const PackTable kPack;

} // namespace

// kHeld: some particle is under a ball (a.touched set): each lane's limit is its held length where
// either end is.
template <bool kHeld>
__attribute__((target("avx2"))) size_t listRows(const ListingArrays& a, const Index* moved, size_t count,
                                                 uint32_t stamp, Index* out, size_t n) {
    const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    const __m256i stampV = _mm256_set1_epi32(int(stamp));
    const __m256i lowByte = _mm256_set1_epi32(0xff);
    const __m256 done = _mm256_set1_ps(a.doneRatio);
    const float* x = reinterpret_cast<const float*>(a.x);
    const int* movedIn = reinterpret_cast<const int*>(a.movedIn);
    const int* listedWords = reinterpret_cast<const int*>(a.listed); // read at byte offsets (scale 1)
    const int* touchedWords = reinterpret_cast<const int*>(a.touched);
    const __m256 limitRatio = _mm256_set1_ps(a.heldDone.limitRatio);
    const __m256 excessRatio = _mm256_set1_ps(a.heldDone.excessRatio);
    const __m256 gauge = _mm256_set1_ps(a.heldDone.gauge);
    for (size_t m = 0; m < count; ++m) {
        const Index p = moved[m];
        const __m256i pTouched = _mm256_set1_epi32(kHeld ? int(a.touched[p]) : 0);
        const __m256i pV = _mm256_set1_epi32(int(p));
        const __m256 px = _mm256_set1_ps(a.x[p].x()), py = _mm256_set1_ps(a.x[p].y()), pz = _mm256_set1_ps(a.x[p].z());
        for (uint32_t k = a.springStart[p], k1 = a.springStart[p + 1]; k < k1; k += 8) {
            const __m256i valid = _mm256_cmpgt_epi32(_mm256_set1_epi32(int(k1 - k)), lane);
            // Lanes past the row read the next row's ends (or the padding): real springs and
            // particles, never taken.
            const __m256i spring = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(a.endSpring + k));
            const __m256i q = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(a.endOther + k));
            const __m256 rest = _mm256_loadu_ps(a.endRest + k);
            const __m256i q3 = _mm256_add_epi32(_mm256_add_epi32(q, q), q);
            const __m256 dx = _mm256_sub_ps(_mm256_i32gather_ps(x, q3, 4), px);
            const __m256 dy = _mm256_sub_ps(_mm256_i32gather_ps(x + 1, q3, 4), py);
            const __m256 dz = _mm256_sub_ps(_mm256_i32gather_ps(x + 2, q3, 4), pz);
            // (x_q - x_p).squaredNorm() as Eigen sums a 3-vector: x^2 + (y^2 + z^2).
            const __m256 len2 =
                _mm256_add_ps(_mm256_mul_ps(dx, dx), _mm256_add_ps(_mm256_mul_ps(dy, dy), _mm256_mul_ps(dz, dz)));
            __m256 limit = _mm256_mul_ps(rest, done);
            if constexpr (kHeld) {
                // heldDone(rest) = limitRatio rest + excessRatio max(rest, gauge), as HeldLength
                // computes it (max_ps(gauge, rest) is std::max(rest, gauge), NaN included).
                const __m256 held = _mm256_add_ps(_mm256_mul_ps(limitRatio, rest),
                                                  _mm256_mul_ps(excessRatio, _mm256_max_ps(gauge, rest)));
                const __m256i qTouched = _mm256_and_si256(_mm256_i32gather_epi32(touchedWords, q, 1), lowByte);
                const __m256i free = _mm256_cmpeq_epi32(_mm256_or_si256(qTouched, pTouched), _mm256_setzero_si256());
                const __m256i underBall = _mm256_xor_si256(free, _mm256_set1_epi32(-1));
                limit = _mm256_blendv_ps(limit, held, _mm256_castsi256_ps(underBall));
            }
            const __m256i over = _mm256_castps_si256(_mm256_cmp_ps(len2, _mm256_mul_ps(limit, limit), _CMP_GT_OQ));
            // Listed from the other end: q < p and this pass moved q too.
            const __m256i qMoved = _mm256_cmpeq_epi32(_mm256_i32gather_epi32(movedIn, q, 4), stampV);
            const __m256i fromOther = _mm256_and_si256(_mm256_cmpgt_epi32(pV, q), qMoved);
            const __m256i flag = _mm256_and_si256(_mm256_i32gather_epi32(listedWords, spring, 1), lowByte);
            const __m256i notListed = _mm256_cmpeq_epi32(flag, _mm256_setzero_si256());
            const __m256i take =
                _mm256_andnot_si256(fromOther, _mm256_and_si256(_mm256_and_si256(valid, over), notListed));
            const unsigned mask = unsigned(_mm256_movemask_ps(_mm256_castsi256_ps(take)));
            if (mask == 0) continue;
            const __m256i pack = _mm256_load_si256(reinterpret_cast<const __m256i*>(kPack.lanes[mask]));
            _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + n), _mm256_permutevar8x32_epi32(spring, pack));
            const size_t taken = size_t(std::popcount(mask));
            for (size_t j = n; j < n + taken; ++j) a.listed[out[j]] = 1;
            n += taken;
        }
    }
    return n;
}

size_t listAvx2(const ListingArrays& a, const Index* moved, size_t count, uint32_t stamp, Index* out, size_t n) {
    return a.touched ? listRows<true>(a, moved, count, stamp, out, n) : listRows<false>(a, moved, count, stamp, out, n);
}
#else
size_t listAvx2(const ListingArrays&, const Index*, size_t, uint32_t, Index*, size_t n) { return n; }
#endif

} // namespace clothtear
