// Building the cloth from a mesh, mass lumping, and the bend-shear spring bookkeeping.
#include "clothtear/cloth.h"

#include "step/revisions.h"
#include "tear_topology.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace clothtear {

double triangleArea(const Vec3d& a, const Vec3d& b, const Vec3d& c) { return 0.5 * (b - a).cross(c - a).norm(); }

double uvArea(const Vec2d& a, const Vec2d& b, const Vec2d& c) {
    const Vec2d e1 = b - a, e2 = c - a;
    return 0.5 * (e1.x() * e2.y() - e1.y() * e2.x());
}

float springWeight(double adjacentArea, double restLength) {
    return static_cast<float>(adjacentArea / (restLength * restLength));
}

// Onal 3.1.2, Eq. 1-4. Angles at the shared corner A of triangles ABC and ABD, from the cosine rule;
// the flat distance |CD| is then the third side of the triangle ACD with angle alpha + beta at A.
double bendRestLength(double e, double ac, double bc, double ad, double bd) {
    auto angle = [](double adj1, double adj2, double opposite) {
        const double c = (adj1 * adj1 + adj2 * adj2 - opposite * opposite) / (2.0 * adj1 * adj2);
        return std::acos(std::clamp(c, -1.0, 1.0));
    };
    const double alpha = angle(e, ac, bc); // Eq. 2 in triangle ABC
    const double beta = angle(e, ad, bd);  // Eq. 2 in triangle ABD
    const double theta = alpha + beta;     // Eq. 3
    return std::sqrt(std::max(0.0, ac * ac + ad * ad - 2.0 * ac * ad * std::cos(theta))); // Eq. 4
}

void refreshSpringWeight(Cloth& cloth, Index s) {
    double area = 0;
    for (Index t : cloth.springTopo[s].tri)
        if (t != kNone) area += cloth.triangles[t].restArea;
    cloth.springs[s].weight = springWeight(area, cloth.springs[s].rest);
}

void Cloth::refreshInvMass(Index p) {
    const double m = particleMass(p);
    invMass[p] = (flags[p] & (kPinned | kAsleep)) || m <= 0.0 ? 0.0f : static_cast<float>(1.0 / m);
    massRevision = nextUniqueRevision();
}

void Cloth::setPinned(Index p, bool on) {
    if (on) flags[p] |= kPinned;
    else flags[p] &= static_cast<uint8_t>(~kPinned);
    refreshInvMass(p);
}

void Cloth::setAsleep(Index p, bool on) {
    if (on) {
        flags[p] |= kAsleep;
        v[p] = Vec3::Zero();
    } else {
        flags[p] &= static_cast<uint8_t>(~kAsleep);
    }
    refreshInvMass(p);
}

void Cloth::setDensity(float d) {
    density = d;
    for (Index p = 0; p < particleCount(); ++p) refreshInvMass(p);
}

double Cloth::totalMass() const {
    double m = 0;
    for (Index p = 0; p < particleCount(); ++p) m += particleMass(p);
    return m;
}

double Cloth::totalRestArea() const {
    double a = 0;
    for (const Triangle& t : triangles) a += t.restArea;
    return a;
}

double Cloth::totalUvArea() const {
    double a = 0;
    for (const Triangle& t : triangles) a += std::abs(uvArea(t.uv[0], t.uv[1], t.uv[2]));
    return a;
}

void removeBendSpring(Cloth& cloth, Index b) {
    cloth.springTopo[cloth.bendEdge[b]].bend = kNone;
    const Index last = static_cast<Index>(cloth.bends.size() - 1);
    if (b != last) {
        cloth.bends[b] = cloth.bends[last];
        cloth.bendEdge[b] = cloth.bendEdge[last];
        if (!cloth.bendMemory.empty()) cloth.bendMemory[b] = cloth.bendMemory[last];
        cloth.springTopo[cloth.bendEdge[b]].bend = b;
    }
    cloth.bends.pop_back();
    cloth.bendEdge.pop_back();
    if (!cloth.bendMemory.empty()) cloth.bendMemory.pop_back();
}

namespace {
// Lengths of the two other sides of triangle t seen from edge s: |A C| and |B C| where A = spring.a.
void sideLengths(const Cloth& cloth, const Triangle& t, Index s, Index& opposite, double& fromA, double& fromB) {
    const int slot = edgeSlotOf(t, s);
    const Spring& sp = cloth.springs[s];
    opposite = t.p[(slot + 2) % 3];
    // The two other springs of the triangle: s[(slot+1)%3] joins p[slot+1] and opposite,
    // s[(slot+2)%3] joins opposite and p[slot].
    const Index s1 = t.s[(slot + 1) % 3], s2 = t.s[(slot + 2) % 3];
    const Index p1 = t.p[(slot + 1) % 3];
    const double l1 = cloth.springs[s1].rest, l2 = cloth.springs[s2].rest;
    // Invariant: the spring in slot i joins exactly p[i] and p[i+1], so p1 is one of its two ends.
    const bool p1IsB = (p1 == sp.b);
    fromB = p1IsB ? l1 : l2;
    fromA = p1IsB ? l2 : l1;
}
} // namespace

void syncBendSpring(Cloth& cloth, Index s) {
    SpringTopo& topo = cloth.springTopo[s];
    if (topo.bend != kNone) removeBendSpring(cloth, topo.bend);
    if (topo.tri[0] == kNone || topo.tri[1] == kNone) return;
    const Triangle& t0 = cloth.triangles[topo.tri[0]];
    const Triangle& t1 = cloth.triangles[topo.tri[1]];
    Index c = kNone, d = kNone;
    double ac = 0, bc = 0, ad = 0, bd = 0;
    sideLengths(cloth, t0, s, c, ac, bc);
    sideLengths(cloth, t1, s, d, ad, bd);
    if (c == d) return; // both triangles share the opposite corner: a degenerate fold, no bend spring
    const double rest = bendRestLength(cloth.springs[s].rest, ac, bc, ad, bd);
    if (!(rest > 0.0)) return;
    Spring bend{c, d, static_cast<float>(rest), springWeight(t0.restArea + t1.restArea, rest)};
    topo.bend = static_cast<Index>(cloth.bends.size());
    // A kes cloth's memory follows the bends (empty: a linear cloth, nothing to follow); a new
    // hinge (a rebuilt bend across a split edge) starts at rest.
    const bool memory = !cloth.bendMemory.empty();
    cloth.bends.push_back(bend);
    cloth.bendEdge.push_back(s);
    if (memory) cloth.bendMemory.push_back(BendMemory{});
}

Result<Cloth> buildCloth(const MeshData& mesh, float density) {
    if (std::string err = checkMesh(mesh, "mesh"); !err.empty()) return Result<Cloth>::failure(err);
    if (mesh.triangles.empty()) return Result<Cloth>::failure("mesh: no triangles");

    // Drop vertices no triangle uses: every particle must belong to a triangle.
    std::vector<Index> remap(mesh.positions.size(), kNone);
    Cloth c;
    c.density = density;
    for (const auto& tri : mesh.triangles)
        for (Index v : tri)
            if (remap[v] == kNone) {
                remap[v] = static_cast<Index>(c.rest.size());
                c.rest.push_back(mesh.positions[v]);
            }
    const size_t n = c.rest.size();
    c.x.resize(n);
    for (size_t i = 0; i < n; ++i) c.x[i] = c.rest[i].cast<float>();
    c.v.assign(n, Vec3::Zero());
    c.invMass.assign(n, 0.f);
    c.areaShare.assign(n, 0.0);
    c.flags.assign(n, 0);
    c.particleTris.assign(n, {});

    std::unordered_map<uint64_t, Index> edgeOf;
    edgeOf.reserve(mesh.triangles.size() * 2);
    c.triangles.reserve(mesh.triangles.size());
    for (size_t ti = 0; ti < mesh.triangles.size(); ++ti) {
        Triangle t{};
        std::array<Index, 3> vertex{}; // the mesh's own vertex of each corner, for messages
        for (int i = 0; i < 3; ++i) {
            vertex[i] = mesh.triangles[ti][i];
            t.p[i] = remap[vertex[i]];
            t.uv[i] = mesh.cornerUVs[ti][i];
        }
        // Keep every triangle counter-clockwise in UV space (flipped OBJ faces are re-ordered).
        if (uvArea(t.uv[0], t.uv[1], t.uv[2]) < 0) {
            std::swap(t.p[1], t.p[2]);
            std::swap(t.uv[1], t.uv[2]);
            std::swap(vertex[1], vertex[2]);
        }
        t.restArea = triangleArea(c.rest[t.p[0]], c.rest[t.p[1]], c.rest[t.p[2]]);
        const Index triIndex = static_cast<Index>(c.triangles.size());
        for (int i = 0; i < 3; ++i) {
            const Index a = t.p[i], b = t.p[(i + 1) % 3];
            const uint64_t key = (uint64_t(std::min(a, b)) << 32) | std::max(a, b);
            auto [it, inserted] = edgeOf.try_emplace(key, static_cast<Index>(c.springs.size()));
            if (inserted) {
                const double len = (c.rest[a] - c.rest[b]).norm();
                c.springs.push_back(Spring{a, b, static_cast<float>(len), 0.f});
                c.springTopo.push_back(SpringTopo{});
            }
            SpringTopo& topo = c.springTopo[it->second];
            if (topo.tri[0] == kNone) topo.tri[0] = triIndex;
            else if (topo.tri[1] == kNone) topo.tri[1] = triIndex;
            else
                return Result<Cloth>::failure("mesh: non-manifold edge between vertices " +
                                              std::to_string(vertex[i] + 1) + " and " +
                                              std::to_string(vertex[(i + 1) % 3] + 1) +
                                              " (shared by 3 or more triangles, face " + std::to_string(ti + 1) + ")");
            t.s[i] = it->second;
        }
        for (int i = 0; i < 3; ++i) {
            c.areaShare[t.p[i]] += t.restArea / 3.0;
            c.particleTris[t.p[i]].push_back(triIndex);
        }
        c.triangles.push_back(t);
    }
    // Two triangles on the same three particles (a doubled face) pass the edge count above, but would
    // give an edge whose two sides are the same triangle twice: no tear could separate them.
    for (Index s = 0; s < c.springs.size(); ++s) {
        const SpringTopo& topo = c.springTopo[s];
        if (topo.tri[1] == kNone) continue;
        const Triangle &t0 = c.triangles[topo.tri[0]], &t1 = c.triangles[topo.tri[1]];
        if (cornerOf(t1, t0.p[0]) >= 0 && cornerOf(t1, t0.p[1]) >= 0 && cornerOf(t1, t0.p[2]) >= 0)
            return Result<Cloth>::failure("mesh: faces " + std::to_string(topo.tri[0] + 1) + " and " +
                                          std::to_string(topo.tri[1] + 1) + " use the same three vertices (a doubled face)");
    }
    for (Index s = 0; s < c.springs.size(); ++s) {
        refreshSpringWeight(c, s);
        syncBendSpring(c, s);
    }
    for (Index p = 0; p < n; ++p) c.refreshInvMass(p);
    // A mesh may come with tear tips (a slit: two vertices at one rest point) or one-point
    // connections (a bow tie): the weak/hinge flags follow the fans from the start.
    for (Index p = 0; p < n; ++p) c.flags[p] |= fanFlags(c, p);
    double restSum = 0;
    for (const Spring& s : c.springs) restSum += s.rest;
    c.minSplitRest = float(kMinSplitFraction * restSum / double(c.springs.size()));
    Result<Cloth> r;
    r.value = std::move(c);
    return r;
}

MeshData clothMesh(const Cloth& cloth, bool restShape) {
    MeshData m;
    m.positions.resize(cloth.particleCount());
    for (Index p = 0; p < cloth.particleCount(); ++p)
        m.positions[p] = restShape ? cloth.rest[p] : Vec3d(cloth.x[p].cast<double>());
    m.triangles.reserve(cloth.triangles.size());
    m.cornerUVs.reserve(cloth.triangles.size());
    for (const Triangle& t : cloth.triangles) {
        m.triangles.push_back({t.p[0], t.p[1], t.p[2]});
        m.cornerUVs.push_back({t.uv[0], t.uv[1], t.uv[2]});
    }
    return m;
}

} // namespace clothtear
