// Local topology helpers for tearing: fans around a particle, appending particles and springs, and
// the bookkeeping that follows a local change. Internal to the core.
#pragma once
#include "clothtear/cloth.h"

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

// After a local change to `triangles`: spring weights and bend-shear springs of their edges, mass
// shares and inverse masses, and the weak/hinge flags of their corners (and the corners' neighbours'
// flags, which depend on the fans). Bumps the topology revision.
void refreshAround(Cloth& cloth, const std::vector<Index>& triangles);

} // namespace clothtear
