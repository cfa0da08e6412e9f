// World::deletePiece: a torn piece taken out of the cloth (issue 14, goal 5). The one topology change
// that is not a tear: the piece's particles, springs, bend-shear springs and triangles go, and the
// rest is renumbered in its order. Particle indices are otherwise stable handles (tearing only
// appends); a deletion happens between frames, at a user's request, and remaps the drivers, the only
// holders of particle indices inside the World (a tool holding one lets go first).
#include "clothtear/world.h"

#include "step/revisions.h"

#include <algorithm>
#include <vector>

namespace clothtear {
namespace {

// Keeps the entries of `v` whose map entry is not kNone, in order.
template <class T>
void compact(std::vector<T>& v, const std::vector<Index>& map) {
    size_t out = 0;
    for (size_t i = 0; i < v.size(); ++i)
        if (map[i] != kNone) {
            if (out != i) v[out] = std::move(v[i]); // a vector moved onto itself would be emptied
            ++out;
        }
    v.resize(out);
}

// New indices for the kept entries, kNone for the others.
std::vector<Index> renumber(const std::vector<bool>& keep) {
    std::vector<Index> map(keep.size(), kNone);
    Index next = 0;
    for (size_t i = 0; i < keep.size(); ++i)
        if (keep[i]) map[i] = next++;
    return map;
}

Index mapped(const std::vector<Index>& map, Index i) { return i == kNone ? kNone : map[i]; }

} // namespace

size_t World::deletePiece(Index triangle) {
    Cloth& c = cloth;
    if (triangle >= c.triangles.size()) return 0;
    // The piece: every particle reached from the triangle's corners through shared triangles.
    std::vector<bool> inPiece(c.particleCount(), false);
    std::vector<Index> stack(c.triangles[triangle].p, c.triangles[triangle].p + 3);
    for (Index p : stack) inPiece[p] = true;
    while (!stack.empty()) {
        const Index p = stack.back();
        stack.pop_back();
        for (Index t : c.particleTris[p])
            for (Index q : c.triangles[t].p)
                if (!inPiece[q]) inPiece[q] = true, stack.push_back(q);
    }
    std::vector<bool> keep(c.particleCount());
    for (size_t p = 0; p < keep.size(); ++p) keep[p] = !inPiece[p];
    const std::vector<Index> newP = renumber(keep);
    keep.assign(c.triangles.size(), false);
    for (size_t t = 0; t < keep.size(); ++t) keep[t] = !inPiece[c.triangles[t].p[0]];
    const std::vector<Index> newT = renumber(keep);
    const size_t removed = c.triangles.size() - std::count(keep.begin(), keep.end(), true);
    keep.assign(c.springs.size(), false);
    for (size_t s = 0; s < keep.size(); ++s) keep[s] = !inPiece[c.springs[s].a];
    const std::vector<Index> newS = renumber(keep);
    keep.assign(c.bends.size(), false);
    for (size_t b = 0; b < keep.size(); ++b) keep[b] = newS[c.bendEdge[b]] != kNone;
    const std::vector<Index> newB = renumber(keep);

    // Particles, with their triangle lists renumbered.
    compact(c.x, newP);
    compact(c.v, newP);
    compact(c.invMass, newP);
    compact(c.areaShare, newP);
    compact(c.rest, newP);
    compact(c.flags, newP);
    compact(c.particleTris, newP);
    for (std::vector<Index>& tris : c.particleTris)
        for (Index& t : tris) t = newT[t];
    // Springs and bend-shear springs: ends and back-references.
    const std::vector<Spring> oldBends = c.bends;
    compact(c.springs, newS);
    compact(c.springTopo, newS);
    for (Spring& s : c.springs) s.a = newP[s.a], s.b = newP[s.b];
    for (SpringTopo& topo : c.springTopo) {
        for (Index& t : topo.tri) t = mapped(newT, t);
        topo.bend = mapped(newB, topo.bend);
    }
    compact(c.bends, newB);
    compact(c.bendEdge, newB);
    if (!c.bendMemory.empty()) compact(c.bendMemory, newB);
    for (Spring& b : c.bends) b.a = newP[b.a], b.b = newP[b.b];
    for (Index& e : c.bendEdge) e = newS[e];
    // Triangles.
    compact(c.triangles, newT);
    for (Triangle& t : c.triangles)
        for (int k = 0; k < 3; ++k) t.p[k] = newP[t.p[k]], t.s[k] = newS[t.s[k]];
    // The drivers (scene hands, clamps) hold particle indices: renumbered, the piece's dropped.
    for (Driver& d : drivers) {
        std::vector<Index> kept;
        for (Index p : d.particles)
            if (p < newP.size() && newP[p] != kNone) kept.push_back(newP[p]);
        d.particles = std::move(kept);
    }
    std::erase_if(drivers, [](const Driver& d) { return d.particles.empty(); });
    c.topologyRevision++;
    c.massRevision = nextUniqueRevision();
    wake();
    return removed;
}

} // namespace clothtear
