// Render vertices from the triangle structure, smoothed normals, per-particle strain.
#include "render_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace clothtear::app {

void RenderMesh::rebuild(const Cloth& cloth) {
    vertexParticle.clear();
    uv.clear();
    indices.clear();
    indices.reserve(cloth.triangles.size() * 3);
    // Per particle: the render vertices made so far with their uv (almost always one; a seam or an
    // OBJ with split UVs gives more). Corner UVs copied from the same vertex compare exactly equal.
    std::vector<std::vector<std::pair<Vec2d, uint32_t>>> seen(cloth.particleCount());
    for (const Triangle& t : cloth.triangles)
        for (int c = 0; c < 3; ++c) {
            auto& list = seen[t.p[c]];
            uint32_t vertex = ~0u;
            for (const auto& [u, v] : list)
                if (u == t.uv[c]) vertex = v;
            if (vertex == ~0u) {
                vertex = uint32_t(vertexParticle.size());
                vertexParticle.push_back(t.p[c]);
                uv.push_back(float(t.uv[c].x()));
                uv.push_back(float(t.uv[c].y()));
                list.emplace_back(t.uv[c], vertex);
            }
            indices.push_back(vertex);
        }
    revision = cloth.topologyRevision;
    particleCount = cloth.particleCount();
}

void computeParticleNormals(const Cloth& cloth, std::vector<Vec3>& normals) {
    normals.assign(cloth.particleCount(), Vec3::Zero());
    for (const Triangle& t : cloth.triangles) {
        // The cross product's length is twice the area: summing it weights by area.
        const Vec3 n = (cloth.x[t.p[1]] - cloth.x[t.p[0]]).cross(cloth.x[t.p[2]] - cloth.x[t.p[0]]);
        for (Index p : t.p) normals[p] += n;
    }
    for (Vec3& n : normals) {
        const float len = n.norm();
        n = len > 1e-20f && std::isfinite(len) ? Vec3(n / len) : Vec3::UnitZ();
    }
}

void computeParticleStrain(const Cloth& cloth, std::vector<float>& strain) {
    strain.assign(cloth.particleCount(), 0.f);
    for (const Spring& s : cloth.springs) {
        if (!(s.rest > 0.f)) continue;
        const float e = (cloth.x[s.b] - cloth.x[s.a]).norm() / s.rest - 1.f;
        strain[s.a] = std::max(strain[s.a], e);
        strain[s.b] = std::max(strain[s.b], e);
    }
}

void fillDynamicVertices(const RenderMesh& mesh, const Cloth& cloth, const std::vector<Vec3>& normals,
                         const std::vector<float>& strain, std::vector<float>& out) {
    out.resize(mesh.vertexCount() * kDynamicFloats);
    float* o = out.data();
    for (Index p : mesh.vertexParticle) {
        const Vec3& x = cloth.x[p];
        const Vec3& n = normals[p];
        o[0] = x.x(), o[1] = x.y(), o[2] = x.z();
        o[3] = n.x(), o[4] = n.y(), o[5] = n.z();
        o[6] = p < strain.size() ? strain[p] : 0.f;
        o += kDynamicFloats;
    }
}

std::vector<Index> findTornEdges(const Cloth& cloth) {
    // Border springs keyed by their rest segment, endpoints in a fixed order: twins sort together.
    struct Key {
        std::array<double, 6> ends;
        Index spring;
    };
    std::vector<Key> border;
    for (Index s = 0; s < Index(cloth.springs.size()); ++s) {
        const SpringTopo& t = cloth.springTopo[s];
        if (t.tri[0] == kNone || t.tri[1] != kNone) continue;
        Vec3d p = cloth.rest[cloth.springs[s].a], q = cloth.rest[cloth.springs[s].b];
        if (std::lexicographical_compare(q.data(), q.data() + 3, p.data(), p.data() + 3)) std::swap(p, q);
        border.push_back({{p.x(), p.y(), p.z(), q.x(), q.y(), q.z()}, s});
    }
    std::sort(border.begin(), border.end(), [](const Key& x, const Key& y) { return x.ends < y.ends; });
    std::vector<Index> torn;
    for (size_t i = 0; i < border.size();) {
        size_t j = i + 1;
        while (j < border.size() && border[j].ends == border[i].ends) ++j;
        if (j - i > 1)
            for (size_t k = i; k < j; ++k) torn.push_back(border[k].spring);
        i = j;
    }
    std::sort(torn.begin(), torn.end());
    return torn;
}

void FringeMesh::rebuild(const Cloth& cloth, float threadsPerUv) {
    edges.clear();
    for (Index s : findTornEdges(cloth)) {
        const Triangle& t = cloth.triangles[cloth.springTopo[s].tri[0]];
        int i = 0;
        while (i < 3 && t.s[i] != s) ++i;
        if (i == 3) continue; // not this triangle's edge: validateCloth would have said so
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        Edge e;
        e.a = t.p[i], e.b = t.p[j], e.c = t.p[k];
        const Vec2d ua = t.uv[i], ub = t.uv[j];
        e.uv[0] = float(ua.x()), e.uv[1] = float(ua.y()), e.uv[2] = float(ub.x()), e.uv[3] = float(ub.y());
        // The threads that cross the edge run across its larger uv direction: warp threads (u = const)
        // for an edge mostly along u, weft threads (v = const) for one mostly along v.
        const int axis = std::abs(ub.x() - ua.x()) >= std::abs(ub.y() - ua.y()) ? 0 : 1;
        e.threads[0] = float(ua[axis] * threadsPerUv);
        e.threads[1] = float(ub[axis] * threadsPerUv);
        // One thread spacing in metres on this edge: its rest length over the threads it crosses.
        const double rest = (cloth.rest[e.b] - cloth.rest[e.a]).norm();
        const double crossed = std::abs(double(e.threads[1]) - e.threads[0]);
        const double spacing = crossed > 1e-6 ? rest / crossed : rest;
        e.reach = float(1.4 * std::min(spacing, rest));
        edges.push_back(e);
    }
    revision = cloth.topologyRevision;
    particleCount = cloth.particleCount();
}

void fillFringeVertices(const FringeMesh& fringe, const Cloth& cloth, const std::vector<Vec3>& normals,
                        std::vector<float>& out) {
    out.resize(fringe.edges.size() * 4 * kFringeFloats);
    float* o = out.data();
    for (const FringeMesh::Edge& e : fringe.edges) {
        const Vec3 &a = cloth.x[e.a], &b = cloth.x[e.b], &c = cloth.x[e.c];
        // Outward in the triangle's plane: from c through the edge, without its part along the edge.
        const Vec3 along = b - a;
        Vec3 out3 = 0.5f * (a + b) - c;
        const float len2 = along.squaredNorm();
        if (len2 > 0) out3 -= along * (out3.dot(along) / len2);
        const float n = out3.norm();
        out3 = n > 1e-12f && std::isfinite(n) ? Vec3(out3 * (e.reach / n)) : Vec3::Zero();
        const Vec3 corners[4] = {a, b, b + out3, a + out3};
        const Vec3* normal[4] = {&normals[e.a], &normals[e.b], &normals[e.b], &normals[e.a]};
        for (int v = 0; v < 4; ++v) {
            const int end = v == 1 || v == 2; // 0: at a, 1: at b
            o[0] = corners[v].x(), o[1] = corners[v].y(), o[2] = corners[v].z();
            o[3] = normal[v]->x(), o[4] = normal[v]->y(), o[5] = normal[v]->z();
            o[6] = e.uv[2 * end], o[7] = e.uv[2 * end + 1];
            o[8] = e.threads[end];
            o[9] = v >= 2 ? 1.f : 0.f;
            o += kFringeFloats;
        }
    }
}

void fringeIndices(size_t edges, std::vector<uint32_t>& out) {
    out.clear();
    out.reserve(edges * 6);
    // (a, b', b) and (a, a', b'): the orientation of the triangle (a, b, c), whose c lies on the other
    // side of the edge from b' and a'.
    for (uint32_t e = 0; e < uint32_t(edges); ++e) {
        const uint32_t a = 4 * e, b = a + 1, bo = a + 2, ao = a + 3;
        out.insert(out.end(), {a, bo, b, a, ao, bo});
    }
}

} // namespace clothtear::app
