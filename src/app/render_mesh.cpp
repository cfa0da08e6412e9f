// Render vertices from the triangle structure, smoothed normals, per-particle strain.
#include "render_mesh.h"

#include <algorithm>
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

} // namespace clothtear::app
