// Tether paths: a breadth-first search over structural springs from every anchor at once. Within
// a breadth-first layer a particle keeps the shortest of the paths that reach it.
#include "tethers.h"

#include <algorithm>

namespace clothtear {

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
    t.springOf.resize(start[n]);
    for (Index i = 0; i < cloth.springs.size(); ++i) {
        t.springOf[fill[cloth.springs[i].a]++] = i;
        t.springOf[fill[cloth.springs[i].b]++] = i;
    }
    t.cut.assign(n, 0);
    t.moved.assign(n, 0);
    t.passStamp = 0;
    t.listed.assign(cloth.springs.size(), 0);

    t.anchor.assign(n, kNone);
    t.length.assign(n, 0.f);
    t.parent.assign(n, kNone);
    t.order.clear();
    t.order.reserve(n);
    t.depth = 0;
    double restSum = 0;
    for (const Spring& s : cloth.springs) restSum += s.rest;
    t.meanRest = cloth.springs.empty() ? 0.f : float(restSum / double(cloth.springs.size()));
    std::vector<uint32_t> layer(n, ~0u);
    for (Index p = 0; p < n; ++p)
        if (anchor[p]) {
            t.anchor[p] = p;
            layer[p] = 0;
            t.order.push_back(p);
        }
    size_t begin = 0;
    for (uint32_t depth = 0; begin < t.order.size(); ++depth) {
        const size_t end = t.order.size();
        for (size_t i = begin; i < end; ++i) {
            const Index p = t.order[i];
            for (uint32_t k = start[p]; k < start[p + 1]; ++k) {
                const Spring& s = cloth.springs[t.springOf[k]];
                const Index o = s.a == p ? s.b : s.a;
                const float len = t.length[p] + s.rest;
                if (layer[o] == ~0u) {
                    layer[o] = depth + 1;
                    t.order.push_back(o);
                } else if (layer[o] != depth + 1 || len >= t.length[o]) {
                    continue;
                }
                t.anchor[o] = t.anchor[p];
                t.length[o] = len;
                t.parent[o] = p;
            }
        }
        begin = end;
        if (begin < t.order.size()) t.depth = depth + 1;
    }
    // The particles a tether pulls: reached, and free (pinned ones never move).
    t.tether.assign(n, kNone);
    for (Index p = 0; p < n; ++p)
        if (t.anchor[p] != kNone && t.anchor[p] != p && cloth.invMass[p] != 0.f) t.tether[p] = t.anchor[p];
}

void markTethersThrough(const LimitCache& t, const std::vector<Index>& seeds, std::vector<uint8_t>& cut) {
    std::fill(cut.begin(), cut.end(), uint8_t(0));
    for (Index p : seeds) cut[p] = 1;
    // Parents come before their children in breadth-first order.
    for (Index p : t.order)
        if (t.parent[p] != kNone && cut[t.parent[p]]) cut[p] = 1;
}

} // namespace clothtear
