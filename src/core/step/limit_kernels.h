// The kernels of the Provot length limit (limit.cpp): the correction of one spring and the
// application of a pass's corrections, with the tolerances the passes and tethers work to.
#pragma once
#include "clothtear/cloth.h"

#include <cmath>
#include <vector>

namespace clothtear {

inline float sq(float a) { return a * a; }

// Springs within this fraction over their limit count as done: at rest every vertical spring sits
// at the limit, and without a tolerance half of them would be "violated" by round-off each pass
// (at rest the springs then sit within 0.2% of their limit: strain 0.1022 for max_stretch 0.1).
inline constexpr float kLimitTolerance = 2e-3f;

// Tethers hold a particle this fraction inside the reach the spring limits allow. A tether exactly
// at that reach makes every spring on the path tight at rest: the Jacobi passes then chase
// round-off from the anchors down a dozen rows every sub-step (hundreds of springs per pass).
// Inside, the springs hanging from the tethers stay below their limit (1%: the curtain hangs at
// 8.9% instead of 10% stretch; 0.2% left a cascade of a few hundred springs per pass at 128x128).
inline constexpr float kTetherSlack = 1e-2f;

// A tether spans a path of structural springs, so a particle is within its reach whenever every
// spring is within the same ratio of its rest length (triangle inequality): the limit then skips the
// tethers (limit.cpp). The scan checks the springs against the reach less this margin, far above the
// float round-off of a path's summed rest lengths and of the distances (~1e-6 relative), so a skip
// is exact: it only ever skips tethers that would not have moved anything. At rest (a curtain at
// strain 0.08) that is every sub-step, and the tethers' checks were 14 % of it at 128 x 128.
inline constexpr float kTetherBoundMargin = 1e-4f;

// The count of the springs a tether pull may have put over the limit (limit.cpp, countMaybeOver)
// takes every spring past the limit less this fraction: a superset of those over it, with room for
// the round-off between two ways of computing a squared length (~1e-6 relative).
inline constexpr float kPrefilterMargin = 1e-5f;

// What addCorrection needs, fixed for the sub-step.
struct CorrectionParams {
    float relaxation;    // limit.relaxation
    float dt;            // s
    bool velocityFix;    // inelastic fix; off for Verlet, whose v is its position change over dt: a move is a velocity
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

// The Provot correction of spring s (longer than maxLen), split by inverse mass, over-relaxed and
// divided by `share`: end a moves by wa c and end b by -wb c; with the velocity fix, end a's
// velocity changes by wa dv and end b's by -wb dv (an inelastic pair: the ends' separating speed
// along the spring is cancelled, up to correction / dt, never reversed; turning the whole
// correction into velocity, v += delta / dt, would inject energy when a long overstretched spring
// is pulled back and set off tear cascades). Verlet (no velocity fix): v is the position change
// over dt, so the move is a velocity change.
struct LimitMove {
    Vec3 c, dv;
};
inline LimitMove limitMove(const Spring& s, const Vec3& d, float len2, float maxLen, float share, const float* invMass,
                           const Vec3* v, const CorrectionParams& P) {
    const float wa = invMass[s.a], wb = invMass[s.b];
    const float len = std::sqrt(len2);
    const float excess = (len - maxLen) * P.relaxation / share;
    const Vec3 n = d / len;
    const Vec3 c = n * (excess / (wa + wb));
    if (!P.velocityFix) return {c, c / P.dt};
    const float separating = (v[s.b] - v[s.a]).dot(n);
    if (!(separating > 0.f)) return {c, Vec3::Zero()};
    return {c, n * (std::min(separating, excess / P.dt) / (wa + wb))};
}

// A Jacobi pass's share of spring s's correction (limitMove), into `corr` and `corrV`, divided by
// `share` (the larger count of corrections its two ends get this pass). Both ends get the same
// fraction of one correction pair, so the pass conserves momentum, as Provot's pairwise correction
// does (dividing each particle's sum by its own count would not).
inline void addCorrection(const Spring& s, const Vec3& d, float len2, float maxLen, float share, const float* invMass,
                          const Vec3* v, const CorrectionParams& P, Corr* corr, Corr* corrV) {
    const float wa = invMass[s.a], wb = invMass[s.b];
    const LimitMove m = limitMove(s, d, len2, maxLen, share, invMass, v, P);
    corr[s.a].head<3>() += wa * m.c;
    corr[s.b].head<3>() -= wb * m.c;
    corrV[s.a].head<3>() += wa * m.dv;
    corrV[s.b].head<3>() -= wb * m.dv;
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

} // namespace clothtear
