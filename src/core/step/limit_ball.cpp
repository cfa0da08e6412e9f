// The length limit where a ball stretches the cloth (limit_ball.h).
#include "limit_ball.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace clothtear {

// The fabric a ball stretches (collision.stretch_band): the particles within that rest distance of
// the corners of a ball's contact triangles, along the structural springs, and not under the ball
// themselves. For this sub-step's limit they count as under the ball (kTouched): their springs may
// stretch to the tear threshold and the tethers through them are cut. Only the contact's own springs
// had that, one ring of springs as long as the mesh spacing, so the fabric a ball could stretch
// shrank with the spacing: the default throw at the 2 m curtain punched a hole at 40 a side, but from
// 80 a side the rest of the curtain, held at the limit, stopped the ball, wrapped it and tore along
// its lower rim (bench/README.md, "The fabric a ball stretches"). A band of fabric in metres is the
// same at every resolution; below the spacing it is the contact's ring, as before.
void markStretchBand(const StepContext& ctx, Cloth& cloth, StepState& state) {
    std::vector<Index>& band = state.stretchBand;
    band.clear();
    const float width = ctx.settings->collision.stretchBand;
    if (!ctx.limiting || state.contacts.empty() || !(width > 0.f)) return;
    const LimitCache& C = state.limit;
    constexpr float kFar = std::numeric_limits<float>::infinity();
    std::vector<float>& dist = state.bandDistance;
    dist.resize(cloth.particleCount(), kFar);
    std::vector<Index>& queue = state.bandQueue; // particles whose distance went down, in the order it did
    queue.clear();
    for (const BallContact& c : state.contacts)
        for (Index p : cloth.triangles[c.triangle].p)
            if (dist[p] != 0.f) {
                dist[p] = 0.f;
                queue.push_back(p);
            }
    for (size_t k = 0; k < queue.size(); ++k) { // shortest rest distances, relaxed in queue order
        const Index p = queue[k];
        for (uint32_t e = C.springStart[p]; e < C.springStart[p + 1]; ++e) {
            const Index q = C.endOther[e];
            const float d = dist[p] + C.endRest[e];
            if (d > width || d >= dist[q]) continue;
            if (dist[q] == kFar && !(cloth.flags[q] & kTouched)) band.push_back(q);
            dist[q] = d;
            queue.push_back(q);
        }
    }
    for (Index p : queue) dist[p] = kFar; // every particle it reached (the corners, the band)
    for (Index q : band) cloth.flags[q] |= kTouched;
}

// Under a ball a spring shorter than tear.gauge_length is held past the tear threshold, up to the
// gauge's stretch (heldLength), and its tension stops growing at the threshold: the excess of its
// elastic force, k x (length - rest x (1 + threshold)), is taken back from this sub-step's
// integration (the kick and the move it gave both ends). The same stretch in metres then costs the
// ball the same force and the same work at every spacing, as a strip of fabric a gauge long that has
// reached its strength would (the crack band model of fracture, Bazant & Oh 1983: past the peak the
// law is scaled by the element's size so that the energy a crack takes does not depend on the mesh).
// Without it the one ring of springs held past the threshold pulls back by its strain, length /
// spacing, and a finer cloth stops the same ball sooner (the default throw at the 4 m curtain, one
// thread: 6.28 m/s left at 128 a side without it, 6.48 with it, 7.02 at 64; bench/README.md).
void capTensionUnderBall(const StepContext& ctx, Cloth& cloth, StepState& state) {
    const SpringCache& S = state.springs;
    const LimitCache& C = state.limit;
    const float strength = ctx.heldRatio, gauge = ctx.tearGauge;
    if (!ctx.limiting || state.contacts.empty() || S.kes || !(gauge > 0.f) || S.entryOf.size() != cloth.springs.size())
        return;
    const float dt = ctx.dt;
    constexpr float kFar = std::numeric_limits<float>::infinity();
    std::vector<float>& seen = state.bandDistance; // every entry +inf between uses (markStretchBand)
    seen.resize(cloth.particleCount(), kFar);
    std::vector<Index>& touched = state.bandQueue;
    touched.clear();
    for (const BallContact& c : state.contacts)
        for (Index p : cloth.triangles[c.triangle].p)
            if (seen[p] != 0.f) seen[p] = 0.f, touched.push_back(p);
    for (Index p : state.stretchBand)
        if (seen[p] != 0.f) seen[p] = 0.f, touched.push_back(p);
    for (Index p : touched) {
        for (uint32_t e = C.springStart[p]; e < C.springStart[p + 1]; ++e) {
            const Index q = C.endOther[e];
            const float rest = C.endRest[e];
            if (!(rest < gauge) || (seen[q] == 0.f && q < p)) continue; // each spring once
            const Vec3 d = cloth.x[q] - cloth.x[p];
            const float len = d.norm(), over = len - rest * strength;
            if (!(over > 0.f)) continue;
            // The force was computed at the start of the sub-step (x - v dt): never take back more
            // than it was. Taken from the length now alone, a spring the sub-step stretched from
            // below the threshold got a push apart it had not been pulled by, and stretched further
            // next time (ball-r2-v3 at 96 a side blew up with gravity at -9.8099).
            const float startLen = ((cloth.x[q] - cloth.v[q] * dt) - (cloth.x[p] - cloth.v[p] * dt)).norm();
            const float excess = std::min(over, startLen - rest * strength);
            if (!(excess > 0.f)) continue;
            const Vec3 kick = d * (S.k[S.entryOf[C.endSpring[e]]] * excess * dt / len); // impulse per unit 1/mass
            const float wp = cloth.invMass[p], wq = cloth.invMass[q];
            cloth.v[p] -= wp * kick, cloth.x[p] -= (wp * dt) * kick;
            cloth.v[q] += wq * kick, cloth.x[q] += (wq * dt) * kick;
            state.packed[p] = packedOf(cloth.x[p], cloth.v[p]);
            state.packed[q] = packedOf(cloth.x[q], cloth.v[q]);
        }
    }
    for (Index p : touched) seen[p] = kFar;
}

// The mean strain of the straightest line of structural springs through spring s that is `gauge`
// long at rest: from each end the spring whose rest direction continues s's most closely (within
// 40 degrees), one side then the other, until the line is the gauge long or ends at a border or a
// tear.
float gaugeStrain(const LimitCache& C, const Cloth& cloth, Index s, float gauge) {
    const Spring& sp = cloth.springs[s];
    const Vec3d axis = (cloth.rest[sp.b] - cloth.rest[sp.a]).normalized();
    double rest = sp.rest, len = (cloth.x[sp.b] - cloth.x[sp.a]).norm();
    Index tip[2] = {sp.b, sp.a}, from[2] = {sp.a, sp.b};
    bool open[2] = {true, true};
    constexpr double kStraight = 0.766; // cos 40 deg: a grid's diagonal (45) does not continue a row
    for (int side = 0; rest < gauge && (open[0] || open[1]); side ^= 1) {
        if (!open[side]) continue;
        const Index p = tip[side];
        const Vec3d dir = side == 0 ? axis : Vec3d(-axis);
        Index best = kNone;
        double bestCos = kStraight;
        float bestRest = 0.f;
        for (uint32_t e = C.springStart[p]; e < C.springStart[p + 1]; ++e) {
            const Index q = C.endOther[e];
            if (q == from[side]) continue;
            const double c = (cloth.rest[q] - cloth.rest[p]).normalized().dot(dir);
            if (c > bestCos) bestCos = c, best = q, bestRest = C.endRest[e];
        }
        if (best == kNone) {
            open[side] = false;
            continue;
        }
        rest += bestRest;
        len += (cloth.x[best] - cloth.x[p]).norm();
        from[side] = p;
        tip[side] = best;
    }
    return float(len / rest - 1.0);
}

} // namespace clothtear
