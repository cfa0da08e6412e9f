// Local topology helpers for tearing (see tear_topology.h).
#include "tear_topology.h"

#include "clothtear/tear.h"

#include <algorithm>

namespace clothtear {

namespace {
// The two springs of triangle t incident to its corner p.
void spokesOf(const Triangle& t, Index p, Index& first, Index& second) {
    const int c = cornerOf(t, p);
    first = t.s[(c + 2) % 3]; // joins p[c+2] and p[c]
    second = t.s[c];          // joins p[c] and p[c+1]
}
Index otherTriangle(const SpringTopo& topo, Index t) { return topo.tri[0] == t ? topo.tri[1] : topo.tri[0]; }

// From t0, leave through spoke `through` and keep crossing spokes around p until a border spoke or
// until back at t0. Appends the spokes crossed (including the final border spoke) and the triangles
// entered. Returns true when the walk came back to t0 (a closed fan). Orientation-agnostic.
bool walkAround(const Cloth& c, Index p, Index t0, Index through, std::vector<Index>& tris, std::vector<Index>& spokes) {
    Index t = t0, e = through;
    for (size_t guard = 0; guard <= c.particleTris[p].size(); ++guard) {
        spokes.push_back(e);
        const Index next = otherTriangle(c.springTopo[e], t);
        if (next == kNone) return false;
        if (next == t0) return true;
        tris.push_back(next);
        Index s1, s2;
        spokesOf(c.triangles[next], p, s1, s2);
        e = (s1 == e) ? s2 : s1;
        t = next;
    }
    return false;
}
} // namespace

std::vector<Fan> fansAround(const Cloth& cloth, Index p) {
    const std::vector<Index>& tris = cloth.particleTris[p];
    std::vector<Fan> fans;
    std::vector<Index> seen;
    for (Index start : tris) {
        if (std::find(seen.begin(), seen.end(), start) != seen.end()) continue;
        Index s1, s2;
        spokesOf(cloth.triangles[start], p, s1, s2);
        std::vector<Index> fwdTris, fwdSpokes;
        Fan fan;
        if (walkAround(cloth, p, start, s2, fwdTris, fwdSpokes)) {
            // Closed: the last spoke crossed leads back into `start`; it precedes start in the chain.
            fan.closed = true;
            fan.tris.push_back(start);
            fan.tris.insert(fan.tris.end(), fwdTris.begin(), fwdTris.end());
            fan.spokes.push_back(fwdSpokes.back());
            fan.spokes.insert(fan.spokes.end(), fwdSpokes.begin(), fwdSpokes.end() - 1);
        } else {
            std::vector<Index> backTris, backSpokes;
            walkAround(cloth, p, start, s1, backTris, backSpokes);
            fan.tris.assign(backTris.rbegin(), backTris.rend());
            fan.tris.push_back(start);
            fan.tris.insert(fan.tris.end(), fwdTris.begin(), fwdTris.end());
            fan.spokes.assign(backSpokes.rbegin(), backSpokes.rend());
            fan.spokes.insert(fan.spokes.end(), fwdSpokes.begin(), fwdSpokes.end());
        }
        seen.insert(seen.end(), fan.tris.begin(), fan.tris.end());
        fans.push_back(std::move(fan));
    }
    return fans;
}

// The same answer as isTearTip(fansAround(p)) / fans.size() > 1, without building the fans: it
// runs for every corner after every tear, and allocating the fan vectors was most of a tear's cost.
// Walks from p's first triangle both ways; fewer triangles reached than p has: two or more fans.
uint8_t fanFlags(const Cloth& cloth, Index p) {
    const std::vector<Index>& tris = cloth.particleTris[p];
    if (tris.empty()) return 0;
    const Index start = tris[0];
    size_t reached = 1;
    // Leaves `start` through spoke e and crosses spokes until a border spoke (returned) or back at
    // start (kNone: closed).
    auto walk = [&](Index e) {
        Index t = start;
        for (size_t guard = 0; guard <= tris.size(); ++guard) {
            const Index next = otherTriangle(cloth.springTopo[e], t);
            if (next == kNone) return e;
            if (next == start) return kNone;
            ++reached;
            Index s1, s2;
            spokesOf(cloth.triangles[next], p, s1, s2);
            e = (s1 == e) ? s2 : s1;
            t = next;
        }
        return kNone;
    };
    Index s1, s2;
    spokesOf(cloth.triangles[start], p, s1, s2);
    const Index last = walk(s2);
    if (last == kNone) return reached < tris.size() ? kHinge : 0; // closed fan
    const Index first = walk(s1);
    if (reached < tris.size()) return kHinge;
    if (reached < 2) return 0; // a tip has at least two triangles (three spokes)
    const Index q1 = otherEnd(cloth.springs[first], p), q2 = otherEnd(cloth.springs[last], p);
    return q1 != q2 && cloth.rest[q1] == cloth.rest[q2] ? kWeak : 0;
}


bool wouldBeScrap(const Cloth& c, Index p, Index seed) {
    // The island of the seed's triangle without p, breadth first in a fixed buffer (this runs in
    // the limit's scan for every spring over its threshold at a hinge): more triangles than the
    // buffer holds is never a scrap.
    constexpr size_t kMaxWalk = 128;
    const double area = minLooseArea(c);
    Index seen[kMaxWalk];
    size_t count = 0;
    seen[count++] = seed;
    double sum = c.triangles[seed].restArea;
    for (size_t next = 0; next < count && sum < area; ++next)
        for (Index q : c.triangles[seen[next]].p) {
            if (q == p) continue;
            for (Index u : c.particleTris[q]) {
                if (std::find(seen, seen + count, u) != seen + count) continue;
                if (count == kMaxWalk) return false;
                seen[count++] = u;
                sum += c.triangles[u].restArea;
                if (sum >= area) return false;
            }
        }
    return sum < area;
}

bool isFlapSpoke(const Cloth& c, Index s) {
    const Index seed = c.springTopo[s].tri[0];
    if (seed == kNone) return false;
    for (Index p : {c.springs[s].a, c.springs[s].b})
        if ((c.flags[p] & kHinge) && wouldBeScrap(c, p, seed)) return true;
    return false;
}

bool isTearTip(const Cloth& cloth, const std::vector<Fan>& fans, Index p) {
    if (fans.size() != 1 || fans[0].closed || fans[0].spokes.size() < 3) return false;
    const Index q1 = otherEnd(cloth.springs[fans[0].spokes.front()], p);
    const Index q2 = otherEnd(cloth.springs[fans[0].spokes.back()], p);
    return q1 != q2 && cloth.rest[q1] == cloth.rest[q2];
}

Index findSpring(const Cloth& cloth, Index a, Index b) {
    if (a >= cloth.particleCount() || b >= cloth.particleCount()) return kNone;
    for (Index t : cloth.particleTris[a])
        for (Index s : cloth.triangles[t].s) {
            const Spring& sp = cloth.springs[s];
            if ((sp.a == a && sp.b == b) || (sp.a == b && sp.b == a)) return s;
        }
    return kNone;
}

Index appendParticleCopy(Cloth& c, Index from) {
    const Index p = Index(c.x.size());
    c.x.push_back(c.x[from]);
    c.v.push_back(c.v[from]);
    c.invMass.push_back(0.f);
    c.areaShare.push_back(0.0);
    c.rest.push_back(c.rest[from]);
    c.flags.push_back(c.flags[from] & kPinned);
    c.particleTris.emplace_back();
    return p;
}

Index appendSpring(Cloth& c, Index a, Index b, double rest) {
    c.springs.push_back(Spring{a, b, float(rest), 0.f});
    c.springTopo.push_back(SpringTopo{});
    return Index(c.springs.size() - 1);
}

void topoAddTriangle(SpringTopo& topo, Index t) {
    if (topo.tri[0] == kNone) topo.tri[0] = t;
    else topo.tri[1] = t;
}
void topoRemoveTriangle(SpringTopo& topo, Index t) {
    if (topo.tri[0] == t) {
        topo.tri[0] = topo.tri[1];
        topo.tri[1] = kNone;
    } else if (topo.tri[1] == t) {
        topo.tri[1] = kNone;
    }
}
void topoReplaceTriangle(SpringTopo& topo, Index from, Index to) {
    for (Index& t : topo.tri)
        if (t == from) t = to;
}
void replaceIn(std::vector<Index>& list, Index from, Index to) {
    for (Index& v : list)
        if (v == from) v = to;
}
void eraseFrom(std::vector<Index>& list, Index value) {
    list.erase(std::remove(list.begin(), list.end(), value), list.end());
}

SplitEnds splitSpring(Cloth& c, Index s, double t, bool separate, std::vector<Index>& touched) {
    const Spring sp = c.springs[s];
    const SpringTopo topo = c.springTopo[s];
    const Index a = sp.a, b = sp.b;
    if (topo.bend != kNone) removeBendSpring(c, topo.bend);
    // (1 - t) a + t b: at t = 1/2 the same bits as (a + b) / 2, so the basic tear is unchanged by
    // sharing this code (halving is exact in binary floating point).
    const Vec3d restM = (1.0 - t) * c.rest[a] + t * c.rest[b];
    const Index ma = appendParticleCopy(c, a), mb = separate ? appendParticleCopy(c, b) : ma;
    c.rest[ma] = c.rest[mb] = restM;
    c.flags[ma] = c.flags[mb] = 0; // new points are never pinned
    if (!separate) {
        c.x[ma] = ((1.0 - t) * c.x[a].cast<double>() + t * c.x[b].cast<double>()).cast<float>();
        c.v[ma] = ((1.0 - t) * c.v[a].cast<double>() + t * c.v[b].cast<double>()).cast<float>();
    }
    // Reuse s as the half a-ma; append the half mb-b.
    c.springs[s] = Spring{a, ma, float(t * double(sp.rest)), 0.f};
    c.springTopo[s] = SpringTopo{};
    const Index hb = appendSpring(c, mb, b, (1.0 - t) * sp.rest);
    for (Index tri : topo.tri) {
        if (tri == kNone) continue;
        const Triangle T = c.triangles[tri];
        const int i = edgeSlotOf(T, s);
        const Index P = T.p[i], Q = T.p[(i + 1) % 3], C = T.p[(i + 2) % 3];
        const Index sQC = T.s[(i + 1) % 3], sCP = T.s[(i + 2) % 3];
        const bool pIsA = (P == a);
        const double tP = pIsA ? t : 1.0 - t; // from P towards Q
        const Vec2d uvM = (1.0 - tP) * T.uv[i] + tP * T.uv[(i + 1) % 3];
        const Index mP = pIsA ? ma : mb, mQ = pIsA ? mb : ma;
        const Index hP = pIsA ? s : hb, hQ = pIsA ? hb : s;
        const double divider = (c.rest[C] - restM).norm();
        const Index dP = appendSpring(c, mP, C, divider);
        const Index dQ = separate ? appendSpring(c, mQ, C, divider) : dP;
        const Index tq = Index(c.triangles.size());
        // P-side part stays in slot tri, Q-side part is appended.
        c.triangles[tri] = Triangle{{P, mP, C}, {hP, dP, sCP}, {T.uv[i], uvM, T.uv[(i + 2) % 3]}, tP * T.restArea};
        c.triangles.push_back(Triangle{
            {mQ, Q, C}, {hQ, sQC, dQ}, {uvM, T.uv[(i + 1) % 3], T.uv[(i + 2) % 3]}, (1.0 - tP) * T.restArea});
        topoAddTriangle(c.springTopo[hP], tri);
        topoAddTriangle(c.springTopo[hQ], tq);
        topoAddTriangle(c.springTopo[dP], tri);
        topoAddTriangle(c.springTopo[dQ], tq);
        topoReplaceTriangle(c.springTopo[sQC], tri, tq);
        replaceIn(c.particleTris[Q], tri, tq);
        c.particleTris[C].push_back(tq);
        c.particleTris[mP].push_back(tri);
        c.particleTris[mQ].push_back(tq);
        touched.push_back(tri);
        touched.push_back(tq);
    }
    return {ma, mb};
}

Index detachGroup(Cloth& c, Index p, const std::vector<Index>& group, std::span<const Index> sharedSpokes,
                  std::vector<Index>& touched) {
    const Index q = appendParticleCopy(c, p);
    for (const Index shared : sharedSpokes) {
        const Spring old = c.springs[shared];
        const Index far = otherEnd(old, p);
        const Index copy = appendSpring(c, q, far, old.rest);
        for (Index t : group) {
            Triangle& T = c.triangles[t];
            const int slot = edgeSlotOf(T, shared);
            if (slot < 0) continue;
            T.s[slot] = copy;
            topoRemoveTriangle(c.springTopo[shared], t);
            topoAddTriangle(c.springTopo[copy], t);
        }
    }
    for (Index t : group) {
        Triangle& T = c.triangles[t];
        const int corner = cornerOf(T, p);
        T.p[corner] = q;
        // The two springs of T at this corner now start at q (unless already moved or the copy).
        for (Index s : {T.s[corner], T.s[(corner + 2) % 3]}) {
            Spring& sp = c.springs[s];
            if (sp.a == p) sp.a = q;
            else if (sp.b == p) sp.b = q;
        }
        eraseFrom(c.particleTris[p], t);
        c.particleTris[q].push_back(t);
        touched.push_back(t);
    }
    if (c.pinned(p)) c.setPinned(q, true);
    return q;
}

void validateAfterChange(const Cloth& c, const TearSettings& settings, TearLog* log) {
#if CLOTHTEAR_VALIDATE_TEARS
    const bool always = true;
#else
    const bool always = false;
#endif
    if (!always && !settings.validate) return;
    const std::string err = validateCloth(c);
    if (!err.empty() && log && log->validationError.empty()) log->validationError = err;
}

void refreshAround(Cloth& c, const std::vector<Index>& triangles) {
    std::vector<Index> springs, particles;
    for (Index t : triangles)
        for (int i = 0; i < 3; ++i) {
            springs.push_back(c.triangles[t].s[i]);
            particles.push_back(c.triangles[t].p[i]);
        }
    std::sort(springs.begin(), springs.end());
    springs.erase(std::unique(springs.begin(), springs.end()), springs.end());
    for (Index s : springs) {
        refreshSpringWeight(c, s);
        syncBendSpring(c, s);
    }
    // Flags depend on the fans of the corners and of their neighbours (a tip moves along the tear).
    std::vector<Index> flagged = particles;
    for (Index s : springs) flagged.push_back(c.springs[s].a), flagged.push_back(c.springs[s].b);
    std::sort(particles.begin(), particles.end());
    particles.erase(std::unique(particles.begin(), particles.end()), particles.end());
    for (Index p : particles) {
        double share = 0;
        for (Index t : c.particleTris[p]) share += c.triangles[t].restArea / 3.0;
        c.areaShare[p] = share;
        c.refreshInvMass(p);
    }
    std::sort(flagged.begin(), flagged.end());
    flagged.erase(std::unique(flagged.begin(), flagged.end()), flagged.end());
    for (Index p : flagged) {
        c.flags[p] = uint8_t((c.flags[p] & ~(kWeak | kHinge)) | fanFlags(c, p));
    }
    c.topologyRevision++;
}

} // namespace clothtear
