// Local topology helpers for tearing: fans around a particle, appending particles and springs, and
// the bookkeeping that follows a local change. Internal to the core.
#pragma once
#include "clothtear/cloth.h"
#include "clothtear/settings.h"
#include "clothtear/tear_events.h"

#include <span>
#include <vector>

namespace clothtear {

// The triangles around particle p that are connected through springs incident to p (its "spokes").
// Ordered as a chain: spokes[0], tris[0], spokes[1], tris[1], ..., with tris[j] between spokes[j]
// and spokes[j+1]. An open fan (p on a border or a torn edge) has tris.size() + 1 spokes, the first
// and last being border springs; a closed fan (p interior) has as many spokes as triangles.
struct Fan {
    std::vector<Index> tris;
    std::vector<Index> spokes;
    bool closed = false;
};

// All fans of p: one for a manifold particle, two or more for a one-point connection.
std::vector<Fan> fansAround(const Cloth& cloth, Index p);

// Tip of a tear (weak point): a single open fan whose two border spokes end in two copies of the
// same rest point, i.e. the two walls of a slit meet at p.
bool isTearTip(const Cloth& cloth, const std::vector<Fan>& fans, Index p);
// kHinge (two or more fans), kWeak (tip of a tear) or 0, from one walk around p.
uint8_t fanFlags(const Cloth& cloth, Index p);

// No confetti (issue 13): would the fan of p that holds triangle `seed`, set loose from p, be an
// island of less rest area than minLooseArea (cloth.h)? Walks the triangles joined to the seed
// through particles other than p (which reaches the whole fan) and stops as soon as it has seen that
// much: a fan still joined to the cloth elsewhere is never a scrap, and the walk stays short.
bool wouldBeScrap(const Cloth& cloth, Index p, Index seed);
// Is spring s a spoke of a fan that a one-point split at its hinge end would keep on as a flap
// (wouldBeScrap)? The limit holds such a spring instead of leaving it to the tear phase: the split
// would not happen, and a flap left overstretched ran away (halved again and again by basic tears,
// forward Euler went non-finite in the random safe-parameter test).
bool isFlapSpoke(const Cloth& cloth, Index s);

// The spring joining particles a and b, or kNone (O(valence)).
Index findSpring(const Cloth& cloth, Index a, Index b);

inline Index otherEnd(const Spring& s, Index p) { return s.a == p ? s.b : s.a; }

// Appends a copy of particle `from` (position, velocity, rest, pin) with no triangles yet.
Index appendParticleCopy(Cloth& cloth, Index from);
// Appends a spring with no triangles yet (weight is set by refreshAround).
Index appendSpring(Cloth& cloth, Index a, Index b, double rest);

void topoAddTriangle(SpringTopo& topo, Index t);
void topoRemoveTriangle(SpringTopo& topo, Index t);
void topoReplaceTriangle(SpringTopo& topo, Index from, Index to);
void replaceIn(std::vector<Index>& list, Index from, Index to);
void eraseFrom(std::vector<Index>& list, Index value);

// The split of a structural spring s = (a, b) at the fraction t from a (0 < t < 1): both neighbour
// triangles are cut from the new point m to their opposite corner (the diagram of the basic tear in
// tear.cpp). `separate`: a and b each get their own copy of m (ma, mb) and each side its own divider,
// so the two halves move apart (the basic tear, t = 1/2, Onal 3.2.1); otherwise one particle m and one
// divider per triangle keep the cloth whole (the knife refines the mesh this way before it cuts
// along the new edges). Rest areas split as t : 1 - t and corner UVs are interpolated at t, so the
// total rest area and UV area stay as they were (3.3). The new particles are unpinned; m's position
// and velocity are interpolated at t (so momentum is kept); ma and mb start as copies of a and b for
// the caller to place. The triangles changed are appended to `touched`; call refreshAround after.
struct SplitEnds {
    Index onA, onB; // the new particle on a's side and on b's side (the same one when not separated)
};
SplitEnds splitSpring(Cloth& cloth, Index s, double t, bool separate, std::vector<Index>& touched);

// Moves the triangles `group` of particle p's fan onto a new copy of p (Onal 3.2.2-3.2.3). Spokes
// that belong only to those triangles move with them; each of `sharedSpokes` is a spoke between the
// group and the rest of the fan: it stays with the rest and the group gets its own copy of it. The
// moved triangles are appended to `touched`. Returns the copy.
Index detachGroup(Cloth& cloth, Index p, const std::vector<Index>& group, std::span<const Index> sharedSpokes,
                  std::vector<Index>& touched);

// After a topology change: validateCloth when Debug builds or tear.validate ask for it; the first
// violation is kept in log->validationError.
void validateAfterChange(const Cloth& cloth, const TearSettings& settings, TearLog* log);

// After a local change to `triangles`: spring weights and bend-shear springs of their edges, mass
// shares and inverse masses, and the weak/hinge flags of their corners (and the corners' neighbours'
// flags, which depend on the fans). Bumps the topology revision.
void refreshAround(Cloth& cloth, const std::vector<Index>& triangles);

} // namespace clothtear
