// Tearing (Onal 3.2-3.3): basic tear, weak points, one-point connections.
//
// Section index:
//   [BASIC]     split both neighbour triangles at the spring's midpoint (3.2.1)
//   [WEAK]      continue a tear through its tip along the thesis heuristic (3.2.2)
//   [ONEPOINT]  separate parts that hang together through one particle (3.2.3)
//   [DRIVER]    candidate ordering, thresholds, cap, events, validation
//
// Texture integrity (3.3): UVs live on triangle corners. Split triangles take the parents' corner UVs
// and the UV midpoint of the torn edge; re-attached triangles keep theirs. Rest areas of split
// triangles are exactly half of the parent's, so the total rest area and the mass (density x area,
// lumped from triangles) never change.
#include "clothtear/tear.h"

#include "tear_tension.h"
#include "tear_topology.h"

#include <algorithm>
#include <cmath>

namespace clothtear {

const char* tearModeName(TearMode m) {
    static const char* names[] = {"basic", "weak_point", "one_point", "knife"};
    return names[int(m)];
}

namespace {

float strainOf(const Cloth& c, Index s) {
    const Spring& sp = c.springs[s];
    return (c.x[sp.b] - c.x[sp.a]).norm() / sp.rest - 1.f;
}

// After a tear the particle that still holds the tense spring is moved towards the spring's other
// end, so the spring is not torn again at once (Onal Fig. 3.9 for the basic tear, Fig. 3.19 for a
// one-point connection): its length drops to at most rest * (1 + target), moving at most half the
// excess. Pinned particles stay.
void relieve(Cloth& c, Index holder, Index spring, float target) {
    if (c.pinned(holder)) return;
    const Spring& sp = c.springs[spring];
    const Index other = otherEnd(sp, holder);
    const Vec3 d = c.x[other] - c.x[holder];
    const float len = d.norm();
    const float excess = len - sp.rest * (1.f + target);
    if (!(excess > 0.f) || !(len > 0.f)) return;
    const Vec3 move = d * (0.5f * excess / len);
    c.x[holder] += move;
}

// ================================================================================================ [BASIC]
//
// Spring s = (a, b) with triangles T1 = (a, b, c) and, unless s is on a border, T2 = (b, a, d).
// Each triangle is split at the midpoint m (splitSpring, tear_topology.cpp: the knife splits with it
// too); a gets its own copy ma, b gets mb:
//
//          c                          c
//         / .                        /|.
//        /   .                      / | .         T1a = (a, ma, c)   T1b = (mb, b, c)
//       /     .          ->        /  |  .        T2a = (ma, a, d)   T2b = (b, mb, d)
//      a-------b                  a--ma mb--b     a-ma and mb-b: the two halves of s, shared
//       .     /                    .  |  /        by the triangles on the same side; the
//        .   /                      . | /         dividers c-ma, c-mb, d-ma, d-mb are separate
//         . /                        .|/          springs, so the two sides move independently.
//          d                          d
//
// The cut runs c - m - d; c and d become tips of the tear (weak points).
bool basicTear(Cloth& c, Index s, float strain, const TearContext& ctx) {
    const Spring sp = c.springs[s];
    const SpringTopo topo = c.springTopo[s];
    const Index a = sp.a, b = sp.b;
    // Never create a degenerate rest triangle or a sliver: an edge of the mesh is halved once, its
    // halves are not (minTearSplitRest, cloth.h).
    double scale = 0;
    for (Index t : topo.tri)
        if (t != kNone) scale = std::max(scale, c.triangles[t].restArea);
    if (!(sp.rest > 1e-6f) || sp.rest < minTearSplitRest(c) || !(scale > 1e-14)) return false;

    std::vector<Index> touched;
    const SplitEnds m = splitSpring(c, s, 0.5, true, touched);
    // Fig. 3.9: place the new ends so that each half is at most slightly stretched.
    const Vec3 d = c.x[b] - c.x[a];
    const float len = d.norm();
    const float half = std::min(0.5f * len, 0.5f * sp.rest * (1.f + 0.5f * ctx.settings.weakThreshold));
    const Vec3 dir = len > 0.f ? Vec3(d / len) : Vec3::Zero();
    c.x[m.onA] = c.x[a] + dir * half;
    c.x[m.onB] = c.x[b] - dir * half;
    // v of the copies = v of their side: momentum is conserved because ma takes exactly the mass a
    // loses (one sixth of each split triangle), likewise mb from b.
    refreshAround(c, touched);
    if (ctx.log) {
        const Triangle& t0 = c.triangles[touched[0]];
        ctx.log->add(TearEvent{TearMode::Basic, ctx.time, c.rest[m.onA], t0.uv[1], strain, sp.rest, sp.weight});
    }
    return true;
}

void addFanTriangles(const Cloth& c, Index p, std::vector<Index>& touched) {
    for (Index t : c.particleTris[p]) touched.push_back(t);
}

Vec2d uvAtParticle(const Cloth& c, Index p) {
    const Triangle& t = c.triangles[c.particleTris[p].front()];
    return t.uv[cornerOf(t, p)];
}

// ================================================================================================= [WEAK]
//
// p is the tip of a tear and spring sT = (p, r) is over the weak threshold. The tear continues
// through p along one of p's other springs (Onal 3.2.2, Fig. 3.13-3.15):
//   1. tension axis t = (x_r - x_p) / |x_r - x_p|;
//   2. the spring that resists most: largest projection of its force on -t;
//   3. the candidates are the springs between sT and that spring on the side where the two are
//      connected through triangles (the other side contains the existing tear);
//   4. among them, the one with the smallest angle to the axis perpendicular to the tension.
// The triangles on the far side of the chosen spring are re-attached to a new copy of p.
// Step 4's tension is the fabric's within tear.tip_radius of p (fabricTensionAxis, tear_tension.h:
// the direction stretched most, the same metres of cloth at every resolution), t where that is not
// defined (radius 0, a held particle that close, no tension); steps 1-3 keep t, which chooses the
// side the tear continues on.
bool weakTear(Cloth& c, Index p, Index sT, float strain, const TearContext& ctx) {
    const Spring tense = c.springs[sT]; // for the event (the split keeps its rest length and weight)
    const std::vector<Fan> fans = fansAround(c, p);
    if (fans.size() != 1 || fans[0].closed) return false;
    const Fan& fan = fans[0];
    const int k = int(fan.tris.size());
    const auto it = std::find(fan.spokes.begin(), fan.spokes.end(), sT);
    if (it == fan.spokes.end()) return false;
    const int iT = int(it - fan.spokes.begin());
    const Index r = otherEnd(c.springs[sT], p);
    Vec3 t = c.x[r] - c.x[p];
    if (!(t.norm() > 0.f)) return false;
    t.normalize();

    int iRes = -1;
    float best = -1e30f;
    for (int j = 0; j <= k; ++j) {
        if (j == iT) continue;
        const Spring& sp = c.springs[fan.spokes[j]];
        Vec3 u = c.x[otherEnd(sp, p)] - c.x[p];
        const float len = u.norm();
        if (!(len > 0.f)) continue;
        u /= len;
        // Force on p of spring j (stiffness weight x extension, along u); a slack spring still
        // counts by direction with a tiny weight so that a choice always exists.
        const float force = sp.weight * std::max(len - sp.rest, 0.f) + 1e-6f * sp.rest;
        const float resistance = force * u.dot(-t);
        if (resistance > best) best = resistance, iRes = j;
    }
    if (iRes < 0) return false;
    const int lo = std::min(iT, iRes), hi = std::max(iT, iRes);
    // With one candidate there is nothing to choose: the fabric is not read.
    Vec3 tension = hi - lo > 2 ? fabricTensionAxis(c, p, fan.tris, ctx.settings.tipRadius) : Vec3::Zero();
    if (tension.squaredNorm() == 0.f) tension = t;
    int iC = -1;
    float bestCos = 2.f;
    for (int j = lo + 1; j < hi; ++j) {
        const Spring& sp = c.springs[fan.spokes[j]];
        const Vec3 u = (c.x[otherEnd(sp, p)] - c.x[p]).normalized();
        const float cosToTension = std::abs(u.dot(tension)); // small = close to the perpendicular axis
        if (cosToTension < bestCos) bestCos = cosToTension, iC = j;
    }
    if (iC < 0) return false;

    const Index cut = fan.spokes[iC];
    const Index farEnd = otherEnd(c.springs[cut], p);
    // Triangles after the cut spoke go to the copy; the cut spoke stays with the triangles before it.
    const std::vector<Index> group(fan.tris.begin() + iC, fan.tris.end());
    std::vector<Index> touched;
    const Index q = detachGroup(c, p, group, std::span<const Index>(&cut, 1), touched);
    addFanTriangles(c, p, touched);
    addFanTriangles(c, farEnd, touched);
    const Index holder = iT >= iC ? q : p;
    refreshAround(c, touched);
    relieve(c, holder, sT, 0.5f * ctx.settings.weakThreshold);
    if (ctx.copies) ctx.copies->emplace_back(p, q);
    if (ctx.log) ctx.log->add(TearEvent{TearMode::WeakPoint, ctx.time, c.rest[p], uvAtParticle(c, p), strain, tense.rest, tense.weight});
    return true;
}

// ============================================================================================= [ONEPOINT]
//
// p joins two or more fans (a tear reached the border, or two tears met): fans leave p, each with
// its own copy of p, and the one holding the tense spring is moved slightly along the tension.
// No confetti (issue 13): a fan that would come loose as a scrap (wouldBeScrap) stays on p with the
// first fan that would not, and hangs there as a flap; if no fan can leave without leaving a scrap
// behind, p is not split (a forced tear, like the thresholds, skips this). Every scrap the drag
// gestures left came from this split (a fan of one or two triangles already cut from the rest on
// its other sides). The flap's own spokes are never tear candidates (isFlapSpoke: the limit holds
// them); a tense spring of another fan at p, with no fan free to leave, is halved by the basic tear
// as at any weak end.
bool onePointSplit(Cloth& c, Index p, Index sT, float strain, const TearContext& ctx, bool keepFlaps) {
    const Spring tense = c.springs[sT]; // for the event
    const std::vector<Fan> fans = fansAround(c, p);
    if (fans.size() < 2) return false;
    std::vector<uint8_t> leaves(fans.size(), 1);
    bool kept = false, anyLeaves = false;
    for (size_t f = 0; f < fans.size(); ++f) {
        const bool scrap = keepFlaps && wouldBeScrap(c, p, fans[f].tris.front());
        if (scrap || !kept) leaves[f] = 0;
        kept |= !scrap;
        anyLeaves |= leaves[f] != 0;
    }
    if (!anyLeaves) return false;
    std::vector<Index> touched;
    addFanTriangles(c, p, touched);
    Index holder = p;
    for (size_t f = 0; f < fans.size(); ++f) {
        if (!leaves[f]) continue;
        const bool holds = std::find(fans[f].spokes.begin(), fans[f].spokes.end(), sT) != fans[f].spokes.end();
        const Index q = detachGroup(c, p, fans[f].tris, {}, touched);
        if (holds) holder = q;
        if (ctx.copies) ctx.copies->emplace_back(p, q);
    }
    refreshAround(c, touched);
    relieve(c, holder, sT, 0.5f * ctx.settings.onePointThreshold);
    if (ctx.log) ctx.log->add(TearEvent{TearMode::OnePoint, ctx.time, c.rest[p], uvAtParticle(c, p), strain, tense.rest, tense.weight});
    return true;
}

// =============================================================================================== [DRIVER]

// Tears spring s if its strain calls for it, choosing the mode from its ends. `force` skips the
// thresholds (topology fuzzing, pre-cut notches).
// `scanStrain` is the strain the scan saw (before the limit pulled other springs back); a tear
// decision uses the larger of it and the current strain.
bool tearOne(Cloth& c, Index s, const TearContext& ctx, bool force, float scanStrain) {
    const TearSettings& T = ctx.settings;
    const float strain = std::max(strainOf(c, s), scanStrain);
    const Index a = c.springs[s].a, b = c.springs[s].b;
    // A hem holds up to its own threshold, whatever else the spring touches (tearStrainFor).
    if (!force && ((c.flags[a] | c.flags[b]) & kHem) && strain < hemThreshold(T)) return false;
    for (Index p : {a, b})
        if ((c.flags[p] & kHinge) && (force || strain >= T.onePointThreshold) && onePointSplit(c, p, s, strain, ctx, !force))
            return true;
    bool weakEnd = false;
    for (Index p : {a, b})
        if ((c.flags[p] & (kWeak | kHinge)) && (force || strain >= weakEndThreshold(T))) {
            weakEnd = true;
            if ((c.flags[p] & kWeak) && weakTear(c, p, s, strain, ctx)) return true;
        }
    // A weak end whose fan offers no path (e.g. the tense spring is a wall of the slit) tears the
    // spring itself: it was exempt from the limit this sub-step and must not stay overstretched.
    if (force || weakEnd || strain >= T.threshold) return basicTear(c, s, strain, ctx);
    return false;
}

} // namespace

int tearSprings(Cloth& c, std::vector<TearCandidate>& candidates, const TearContext& ctx) {
    // Most strained first; ties by index so the order is deterministic.
    std::sort(candidates.begin(), candidates.end(), [](const TearCandidate& x, const TearCandidate& y) {
        return x.strain != y.strain ? x.strain > y.strain : x.spring < y.spring;
    });
    // Springs are renumbered as tears append; remember candidates by their particles.
    struct Ends {
        Index a, b;
        float strain;
    };
    std::vector<Ends> ends;
    ends.reserve(candidates.size());
    for (const TearCandidate& k : candidates)
        if (k.spring < c.springs.size()) ends.push_back({c.springs[k.spring].a, c.springs[k.spring].b, k.strain});
    int tears = 0;
    for (const Ends& e : ends) {
        if (tears >= ctx.settings.maxPerStep) break;
        const Index s = findSpring(c, e.a, e.b);
        if (s == kNone) continue;
        if (tearOne(c, s, ctx, false, e.strain)) {
            ++tears;
            validateAfterChange(c, ctx.settings, ctx.log);
        }
    }
    return tears;
}

bool forceTear(Cloth& c, Index s, const TearContext& ctx) {
    if (s >= c.springs.size()) return false;
    const bool torn = tearOne(c, s, ctx, true, 0.f);
    if (torn) validateAfterChange(c, ctx.settings, ctx.log);
    return torn;
}

} // namespace clothtear
