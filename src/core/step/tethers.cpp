// Tether paths: a breadth-first search over structural springs from a set of anchors at once.
// Within a breadth-first layer a particle keeps the shortest of the paths that reach it.
#include "tethers.h"

#include <algorithm>
#include <cmath>

namespace clothtear {
namespace {

// Fills `set` with the paths from `sources` (anchors) to every particle they reach; returns the
// depth in springs of the farthest one. Particles with invMass 0 get no tether (nothing moves them).
uint32_t breadthFirst(const Cloth& cloth, const LimitCache& t, const std::vector<Index>& sources, TetherSet& set) {
    const size_t n = cloth.particleCount();
    // The layer of each particle reached (~0u: not yet) and its anchor, in one place: the search
    // reads both of a neighbour together.
    struct Reach {
        uint32_t layer;
        Index anchor;
    };
    std::vector<Reach> reach(n, Reach{~0u, kNone});
    set.length.assign(n, 0.f);
    set.parent.assign(n, kNone);
    set.cut.assign(n, 0);
    // The queue is the order itself, written through a pointer: no particle enters twice, so n
    // entries hold it. Members in locals: the stores into the per-particle arrays may alias the
    // table's and the vectors' own words, and the compiler reloaded them after each store.
    set.order.resize(sources.empty() ? 0 : n);
    Index* order = set.order.data();
    float* length = set.length.data();
    Index* parent = set.parent.data();
    Reach* r = reach.data();
    const uint32_t* start = t.springStart.data();
    const Index* endOther = t.endOther.data();
    const float* endRest = t.endRest.data();
    size_t queued = 0;
    for (Index p : sources) {
        r[p] = Reach{0, p};
        order[queued++] = p;
    }
    uint32_t deepest = 0;
    size_t begin = 0;
    for (uint32_t depth = 0; begin < queued; ++depth) {
        const size_t end = queued;
        const uint32_t next = depth + 1;
        for (size_t i = begin; i < end; ++i) {
            const Index p = order[i];
            const float lp = length[p];
            const Index ap = r[p].anchor;
            // The particle-spring table's own copies of the other end and the rest length: read in
            // row order, not through the spring. Within a layer a particle keeps the shortest of
            // the paths that reach it (the first of equal ones).
            for (uint32_t k = start[p], k1 = start[p + 1]; k < k1; ++k) {
                const Index o = endOther[k];
                const float len = lp + endRest[k];
                if (r[o].layer == ~0u) {
                    r[o].layer = next;
                    order[queued++] = o;
                } else if (r[o].layer != next || len >= length[o]) {
                    continue;
                }
                r[o].anchor = ap;
                length[o] = len;
                parent[o] = p;
            }
        }
        begin = end;
        if (begin < queued) deepest = next;
    }
    set.order.resize(queued);
    // The particles a tether pulls: reached, and free (pinned ones never move).
    set.tether.assign(n, kNone);
    for (Index p = 0; p < n; ++p)
        if (r[p].anchor != kNone && r[p].anchor != p && cloth.invMass[p] != 0.f) set.tether[p] = r[p].anchor;
    return deepest;
}

// The two anchors farthest apart at rest (the second is the farthest from the first, which is the
// farthest from the lowest-numbered anchor): the ends of a pinned edge, the two pinned corners.
// Fewer than two anchors: none.
std::array<Index, 2> spanEnds(const Cloth& cloth, const std::vector<Index>& anchors) {
    if (anchors.size() < 2) return {kNone, kNone};
    auto farthestFrom = [&](Index from) {
        Index best = anchors[0];
        double bestD2 = -1.0;
        for (Index a : anchors) {
            const double d2 = (cloth.rest[a] - cloth.rest[from]).squaredNorm();
            if (d2 > bestD2) bestD2 = d2, best = a;
        }
        return best;
    };
    const Index first = farthestFrom(anchors[0]);
    return {first, farthestFrom(first)};
}

} // namespace

void buildLimitCache(const Cloth& cloth, const std::vector<uint8_t>& anchor, LimitCache& t) {
    const size_t n = cloth.particleCount();
    // Structural springs per particle (compressed rows).
    std::vector<uint32_t>& start = t.springStart;
    start.assign(n + 1, 0);
    for (const Spring& s : cloth.springs) {
        start[s.a + 1]++;
        start[s.b + 1]++;
    }
    for (size_t p = 0; p < n; ++p) start[p + 1] += start[p];
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    const size_t entries = start[n] + LimitCache::kEndsPadding;
    t.endSpring.assign(entries, 0);
    t.endOther.assign(entries, 0);
    t.endRest.assign(entries, 0.f);
    for (Index i = 0; i < cloth.springs.size(); ++i) {
        const Spring& s = cloth.springs[i];
        for (const auto& [end, other] : {std::pair{s.a, s.b}, std::pair{s.b, s.a}}) {
            const uint32_t k = fill[end]++;
            t.endSpring[k] = i;
            t.endOther[k] = other;
            t.endRest[k] = s.rest;
        }
    }
    t.regionBin.clear(); // built when the passes run on several threads (buildRegionBins)
    t.moved.assign(n, 0);
    t.passStamp = 0;
    t.listed.assign(cloth.springs.size() + LimitCache::kFlagPadding, 0);
    t.touched.assign(n + LimitCache::kFlagPadding, 0);
    t.candidate.assign(cloth.springs.size(), 0);
    double restSum = 0;
    for (const Spring& s : cloth.springs) restSum += s.rest;
    t.meanRest = cloth.springs.empty() ? 0.f : float(restSum / double(cloth.springs.size()));

    std::vector<Index> anchors;
    for (Index p = 0; p < n; ++p)
        if (anchor[p]) anchors.push_back(p);
    t.depth = breadthFirst(cloth, t, anchors, t.tethers[0]);
    const std::array<Index, 2> ends = spanEnds(cloth, anchors);
    for (int e = 0; e < 2; ++e) {
        std::vector<Index> source;
        if (ends[e] != kNone) source.push_back(ends[e]);
        breadthFirst(cloth, t, source, t.tethers[1 + e]);
    }
}

// The bins along the axis of rest space whose bins follow the particles' numbering best (the rows
// of a grid): a region is then mostly a run of numbers, and two threads' particles, springs and
// flags seldom share a cache line (bins along the longer side of a square curtain, its columns,
// made the passes slower than one thread's).
void buildRegionBins(const Cloth& cloth, LimitCache& t) {
    const size_t n = cloth.particleCount();
    t.regionBin.assign(n, 0);
    if (n > 0) {
        Vec3d lo = cloth.rest[0], hi = cloth.rest[0];
        for (const Vec3d& r : cloth.rest) lo = lo.cwiseMin(r), hi = hi.cwiseMax(r);
        std::vector<uint8_t> bins(n);
        size_t bestRuns = 0;
        bool found = false;
        for (int axis = 0; axis < 3; ++axis) {
            const double width = hi[axis] - lo[axis];
            if (!(width > 0) || !std::isfinite(width)) continue;
            const double scale = double(LimitCache::kRegionBins) / width;
            size_t runs = 0; // consecutive particles in one bin
            for (size_t p = 0; p < n; ++p) {
                const double b = std::floor((cloth.rest[p][axis] - lo[axis]) * scale);
                bins[p] = uint8_t(b > 0.0 ? std::min(b, double(LimitCache::kRegionBins - 1)) : 0.0); // NaN: 0
                runs += p > 0 && bins[p] == bins[p - 1];
            }
            if (!found || runs > bestRuns) {
                found = true;
                bestRuns = runs;
                t.regionBin.swap(bins);
                bins.resize(n);
            }
        }
    }
}

void markTethersThrough(TetherSet& set, const std::vector<Index>& seeds) {
    std::fill(set.cut.begin(), set.cut.end(), uint8_t(0));
    for (Index p : seeds) set.cut[p] = 1;
    // Parents come before their children in breadth-first order.
    for (Index p : set.order)
        if (set.parent[p] != kNone && set.cut[set.parent[p]]) set.cut[p] = 1;
}

} // namespace clothtear
