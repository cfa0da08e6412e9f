// randomTears (topology_gen.h), a template so each caller's check inlines.
#pragma once
#include "clothtear/cloth.h"

#include <vector>

namespace topofuzz {

template <class Check>
TearStats randomTears(clothtear::Cloth& c, clothtear::Rng& rng, int count, Check&& check) {
    using namespace clothtear;
    TearStats st;
    TearSettings settings;
    TearLog log;
    const TearContext ctx{settings, 0.0, &log};
    Index last = kNone; // the spring torn last
    bool ok = true;     // false once `check` said stop
    auto tear = [&](Index s) {
        ++st.tried;
        if (!forceTear(c, s, ctx))
            return;
        ++st.torn;
        last = s;
        ok = check(st.torn);
    };
    while (ok && int(st.torn) < count && st.tried < uint64_t(count) * 20) {
        const double pick = rng.uniform();
        if (pick < 0.45 || last == kNone) {
            // A random spring anywhere.
            tear(rng.below(uint32_t(c.springs.size())));
        } else if (pick < 0.9) {
            // The same place again: the spring just torn keeps its index (it became one of the
            // halves), or a spring at one of its ends.
            ++st.repeated;
            Index s = last < c.springs.size() ? last : rng.below(uint32_t(c.springs.size()));
            if (rng.uniform() < 0.5) {
                const Index p = rng.uniform() < 0.5 ? c.springs[s].a : c.springs[s].b;
                const auto& tris = c.particleTris[p];
                if (!tris.empty())
                    s = c.triangles[tris[rng.below(uint32_t(tris.size()))]].s[rng.below(3)];
            }
            tear(s);
        } else {
            // A cut: every spring crossing a random line in rest space, in random order, for a few
            // rounds (a tear's new dividers may cross the line too); the cloth usually falls into
            // more pieces. Capped, as halving springs across the line would go on to the shortest
            // edge the tear code splits.
            ++st.cutLines;
            const size_t before = pieceCount(c);
            Vec3d lo = c.rest[0], hi = c.rest[0];
            for (const Vec3d& r : c.rest)
                lo = lo.cwiseMin(r), hi = hi.cwiseMax(r);
            const Vec3d at(rng.uniform(lo.x(), hi.x()), rng.uniform(lo.y(), hi.y()), 0.0);
            const double angle = rng.uniform(0.0, 3.14159265358979);
            const Vec3d normal(std::cos(angle), std::sin(angle), 0.0);
            auto side = [&](Index p) { return (c.rest[p] - at).dot(normal) > 0.0; };
            int cutBudget = -1;
            for (int round = 0; round < 3 && ok && cutBudget != 0 && int(st.torn) < count; ++round) {
                std::vector<Index> crossing;
                for (Index s = 0; s < c.springs.size(); ++s)
                    if (side(c.springs[s].a) != side(c.springs[s].b))
                        crossing.push_back(s);
                if (crossing.empty())
                    break;
                if (cutBudget < 0)
                    cutBudget = 2 * int(crossing.size()) + 8;
                // Shuffle (Fisher-Yates), then tear by the particles: indices move as tears append.
                for (size_t i = crossing.size(); i > 1; --i)
                    std::swap(crossing[i - 1], crossing[rng.below(uint32_t(i))]);
                std::vector<std::pair<Index, Index>> ends;
                for (Index s : crossing)
                    ends.emplace_back(c.springs[s].a, c.springs[s].b);
                for (const auto& [a, b] : ends) {
                    Index s = kNone;
                    for (Index t : c.particleTris[a])
                        for (Index e : c.triangles[t].s)
                            if ((c.springs[e].a == a && c.springs[e].b == b) ||
                                (c.springs[e].a == b && c.springs[e].b == a))
                                s = e;
                    if (s == kNone)
                        continue;
                    tear(s);
                    if (!ok || int(st.torn) >= count || --cutBudget <= 0)
                        break;
                }
            }
            const size_t after = pieceCount(c);
            if (after > before)
                st.piecesCut += after - before;
        }
    }
    for (int m = 0; m < 3; ++m)
        st.modes[m] = log.counts[m];
    return st;
}

} // namespace topofuzz
