// The limit's listing after a pass (limit.cpp, LimitSolve::expand): of the structural springs of the
// particles a pass moved, those now over the limit and not listed yet go on the list. Under a moving
// hand every sub-step runs its Gauss-Seidel passes to the cap, each followed by this listing of some
// 2,500 springs (a 128 x 128 curtain): a quarter of the window's simulation thread while the hand
// tears (bench/README.md, "The listing eight springs at a time").
//
// Here eight springs of a particle's row at a time with AVX2: their other ends and rest lengths
// loaded, their listed flags and the other ends' positions, move stamps (and under a ball, touched
// marks) gathered, the same tests lane by lane, and the taken springs' indices packed in row order.
// The list, the flags and so the passes come out to the bit as the scalar loop's (the squared
// length in Eigen's order, no fused multiply-add); a test compares the two.
#pragma once
#include "clothtear/cloth.h"
#include "step_context.h"
#include "step_state.h"

#include <cstddef>
#include <cstdint>

namespace clothtear {

// What a listing reads and writes. A spring with an end under a ball (kTouched) is over when longer
// than its held length (heldLength), any other when longer than rest x doneRatio (limit.cpp,
// exceedsLimit).
struct ListingArrays {
    const uint32_t* springStart; // LimitCache::springStart, endSpring, endOther and endRest (padded)
    const Index* endSpring;
    const Index* endOther;
    const float* endRest;
    const Vec3* x;               // positions
    const uint32_t* movedIn;     // LimitCache::moved: the pass's stamp on each particle it moved
    uint8_t* listed;             // LimitCache::listed (padded: LimitCache::kFlagPadding)
    float doneRatio;             // a spring longer than rest x doneRatio is over
    // Per particle (LimitCache::touched, padded): non-zero where kTouched is set; null when no
    // particle is.
    const uint8_t* touched;
    HeldLength heldDone; // under a ball: over when longer than heldDone(rest)
};

// Does this CPU run listAvx2 (CLOTHTEAR_LISTING_KERNEL=scalar says no, for the tests and benchmarks
// that compare the two)?
bool listingAvx2Available();

// Lists, after out[0, n), the springs the scalar loop would (limit.cpp, LimitSolve::expand), in its
// order: for each particle p of moved[0, count), the springs of p's row, in row order, over the
// limit, not listed, and not to a particle q < p that this pass moved too (listed from q). Sets their
// flags. out must have room for 8 entries past the last one written. Returns the new count. No
// other thread may list at the same time (the flags are read without atomics).
size_t listAvx2(const ListingArrays& a, const Index* moved, size_t count, uint32_t stamp, Index* out, size_t n);

} // namespace clothtear
