// validateCloth: every topology invariant of the cloth, checked in one place. Runs after each tear
// in Debug builds and when tear.validate is on; the tests call it after every tear of long runs.
#include "clothtear/tear.h"

#include "tear_topology.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <unordered_set>

namespace clothtear {
namespace {
std::string at(const char* what, size_t i) {
    std::ostringstream o;
    o << what << " " << i << ": ";
    return o.str();
}
bool relClose(double a, double b, double tol) { return std::abs(a - b) <= tol * std::max(std::abs(a), std::abs(b)); }

// All the digits: to_string's six decimals print tiny areas as 0.000000.
std::string precise(double v) {
    std::ostringstream o;
    o.precision(17);
    o << v;
    return o.str();
}

// What rounding can move a UV area by. uvArea is a difference of two products of edge vectors that
// are themselves differences of corners; for a sliver the products are far larger than the area, so
// the area carries their round-off, not its own (found by fuzz_obj: sliver UV triangles of 5.6e-9 in
// all, three splits later, summed 2.2e-9 of themselves off). A split corner (the midpoint of an
// edge) is rounded relative to the corners' magnitude. So the bound is a few eps times the edge
// lengths times (edge lengths + corner magnitude) per triangle: a lost triangle of any area above
// that (every triangle the importer takes is above 1e-12 of the sheet) still fails.
double uvRoundOff(const Vec2d& a, const Vec2d& b, const Vec2d& c) {
    const double edges = (b - a).cwiseAbs().maxCoeff() + (c - a).cwiseAbs().maxCoeff();
    return 1e-15 * edges * (edges + a.cwiseAbs().maxCoeff());
}
} // namespace

std::string validateCloth(const Cloth& c, double expectedArea, double expectedUvArea) {
    const size_t np = c.particleCount(), ns = c.springs.size(), nt = c.triangles.size(), nb = c.bends.size();
    if (c.v.size() != np || c.invMass.size() != np || c.areaShare.size() != np ||
        c.rest.size() != np || c.flags.size() != np || c.particleTris.size() != np)
        return "particle arrays differ in length";
    if (c.springTopo.size() != ns) return "spring arrays differ in length";
    if (c.bendEdge.size() != nb) return "bend arrays differ in length";
    if (!c.bendMemory.empty() && c.bendMemory.size() != nb) return "bend memory (kes hinges) differs in length from the bends";

    for (size_t t = 0; t < nt; ++t) {
        const Triangle& tri = c.triangles[t];
        for (int i = 0; i < 3; ++i) {
            if (tri.p[i] >= np) return at("triangle", t) + "particle index out of range";
            if (tri.s[i] >= ns) return at("triangle", t) + "spring index out of range";
        }
        if (tri.p[0] == tri.p[1] || tri.p[1] == tri.p[2] || tri.p[0] == tri.p[2]) return at("triangle", t) + "repeats a particle";
        for (int i = 0; i < 3; ++i) {
            const Spring& s = c.springs[tri.s[i]];
            const Index a = tri.p[i], b = tri.p[(i + 1) % 3];
            if (!((s.a == a && s.b == b) || (s.a == b && s.b == a)))
                return at("triangle", t) + "spring in slot " + std::to_string(i) + " does not join its corners";
            const SpringTopo& topo = c.springTopo[tri.s[i]];
            if (topo.tri[0] != t && topo.tri[1] != t) return at("triangle", t) + "its spring does not list it";
            bool listed = false;
            for (Index q : c.particleTris[tri.p[i]]) listed |= (q == t);
            if (!listed) return at("triangle", t) + "corner particle does not list it";
        }
        const double area = triangleArea(c.rest[tri.p[0]], c.rest[tri.p[1]], c.rest[tri.p[2]]);
        if (!(tri.restArea > 0.0)) return at("triangle", t) + "degenerate (zero rest area)";
        // Slivers from repeated halving lose relative precision in the cross product; compare
        // against the squared edge scale instead.
        const double edge2 = std::max({(c.rest[tri.p[1]] - c.rest[tri.p[0]]).squaredNorm(),
                                       (c.rest[tri.p[2]] - c.rest[tri.p[1]]).squaredNorm(),
                                       (c.rest[tri.p[0]] - c.rest[tri.p[2]]).squaredNorm()});
        if (std::abs(area - tri.restArea) > 1e-9 * edge2) return at("triangle", t) + "cached rest area does not match rest positions";
        if (!(uvArea(tri.uv[0], tri.uv[1], tri.uv[2]) > 0.0)) return at("triangle", t) + "UV triangle is not counter-clockwise";
    }

    std::unordered_set<uint64_t> pairs;
    pairs.reserve(ns * 2);
    for (size_t s = 0; s < ns; ++s) {
        const Spring& sp = c.springs[s];
        const SpringTopo& topo = c.springTopo[s];
        if (sp.a >= np || sp.b >= np || sp.a == sp.b) return at("spring", s) + "bad particle indices";
        if (!(sp.rest > 0.f)) return at("spring", s) + "non-positive rest length";
        if (topo.tri[0] == kNone) return at("spring", s) + "has no triangle";
        if (topo.tri[0] == topo.tri[1]) return at("spring", s) + "lists the same triangle twice";
        for (Index t : topo.tri) {
            if (t == kNone) continue;
            if (t >= nt) return at("spring", s) + "triangle index out of range";
            if (edgeSlotOf(c.triangles[t], Index(s)) < 0) return at("spring", s) + "listed triangle does not contain it";
        }
        // Two triangles on opposite sides of a torn edge must not share both particles along it:
        // that would be two springs on the same particle pair.
        const uint64_t key = (uint64_t(std::min(sp.a, sp.b)) << 32) | std::max(sp.a, sp.b);
        if (!pairs.insert(key).second) return at("spring", s) + "another spring joins the same two particles";
        const bool interior = topo.tri[1] != kNone;
        if (topo.bend != kNone) {
            if (topo.bend >= nb || c.bendEdge[topo.bend] != s) return at("spring", s) + "bend back-reference broken";
            if (!interior) return at("spring", s) + "border edge has a bend-shear spring";
        }
    }

    for (size_t b = 0; b < nb; ++b) {
        const Index e = c.bendEdge[b];
        if (e >= ns || c.springTopo[e].bend != b) return at("bend", b) + "edge back-reference broken";
        const SpringTopo& topo = c.springTopo[e];
        if (topo.tri[1] == kNone) return at("bend", b) + "crosses an edge that is not interior";
        Index opp[2];
        for (int k = 0; k < 2; ++k) {
            const Triangle& t = c.triangles[topo.tri[k]];
            opp[k] = t.p[(edgeSlotOf(t, e) + 2) % 3];
        }
        const Spring& bs = c.bends[b];
        if (!((bs.a == opp[0] && bs.b == opp[1]) || (bs.a == opp[1] && bs.b == opp[0])))
            return at("bend", b) + "does not join the opposite corners of its edge's triangles";
    }

    double totalArea = 0, totalUv = 0, uvSlack = 0;
    std::vector<double> share(np, 0.0);
    for (size_t t = 0; t < nt; ++t) {
        const Triangle& tri = c.triangles[t];
        totalArea += tri.restArea;
        totalUv += uvArea(tri.uv[0], tri.uv[1], tri.uv[2]);
        uvSlack += uvRoundOff(tri.uv[0], tri.uv[1], tri.uv[2]);
        for (Index p : tri.p) share[p] += tri.restArea / 3.0;
    }
    for (size_t p = 0; p < np; ++p) {
        if (c.particleTris[p].empty()) return at("particle", p) + "belongs to no triangle";
        for (Index t : c.particleTris[p])
            if (t >= nt || cornerOf(c.triangles[t], Index(p)) < 0) return at("particle", p) + "lists a triangle it is not a corner of";
        if (!relClose(share[p], c.areaShare[p], 1e-9)) return at("particle", p) + "mass share does not match its triangles";
        if (!c.x[p].allFinite() || !c.v[p].allFinite()) return at("particle", p) + "non-finite position or velocity";
    }
    // Weak-point and hinge flags (Onal 3.2.2, 3.2.3) as the fans say, built the slow way here.
    for (size_t p = 0; p < np; ++p) {
        const std::vector<Fan> fans = fansAround(c, Index(p));
        const uint8_t expected = fans.size() > 1 ? kHinge : isTearTip(c, fans, Index(p)) ? kWeak : 0;
        if ((c.flags[p] & (kWeak | kHinge)) != expected) return at("particle", p) + "weak/hinge flag does not match its fans";
    }
    if (expectedArea > 0 && !relClose(totalArea, expectedArea, 1e-9))
        return "total rest area changed: " + precise(totalArea) + " vs " + precise(expectedArea);
    // The expected total was summed from the original triangles, whose products are at most this
    // large too (a split halves an edge): twice the slack covers both sums.
    if (expectedUvArea > 0 && !(std::abs(totalUv - expectedUvArea) <= 1e-9 * std::max(totalUv, expectedUvArea) + 2 * uvSlack))
        return "total UV area changed: " + precise(totalUv) + " vs " + precise(expectedUvArea);
    return {};
}

} // namespace clothtear
