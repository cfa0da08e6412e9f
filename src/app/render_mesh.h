// The CPU side of the cloth's GPU mesh: one render vertex per (particle, uv) pair, so the texture stays
// intact across a tear (Onal 3.3) while shared corners keep one smoothed normal. No GL here: the
// renderer uploads these arrays; tests check them without a window.
//
//   static data (re-uploaded when cloth.topologyRevision changes): vertexParticle, uv, indices
//   dynamic data (every frame):                                    position, normal, strain per vertex
#pragma once
#include "clothtear/cloth.h"

#include <cstdint>
#include <vector>

namespace clothtear::app {

struct RenderMesh {
    std::vector<Index> vertexParticle; // particle of each render vertex
    std::vector<float> uv;             // 2 per render vertex
    std::vector<uint32_t> indices;     // 3 per triangle, into the render vertices
    uint64_t revision = ~uint64_t(0);  // cloth.topologyRevision these were built from
    size_t particleCount = 0;          // particles when built (tearing appends particles)

    size_t vertexCount() const { return vertexParticle.size(); }
    // True when the static data no longer matches the cloth.
    bool stale(const Cloth& cloth) const {
        return revision != cloth.topologyRevision || particleCount != cloth.particleCount() ||
               indices.size() != cloth.triangles.size() * 3;
    }
    void rebuild(const Cloth& cloth);
};

// Area-weighted smooth normals per particle, from its incident triangles only (a torn side has its own
// particles, so normals never average across a tear). Isolated or degenerate particles get +z.
void computeParticleNormals(const Cloth& cloth, std::vector<Vec3>& normals);

// Largest strain (len / rest - 1) over the structural springs touching each particle.
void computeParticleStrain(const Cloth& cloth, std::vector<float>& strain);

// Interleaved dynamic vertex data: position (3), normal (3), strain (1) per render vertex.
inline constexpr int kDynamicFloats = 7;
void fillDynamicVertices(const RenderMesh& mesh, const Cloth& cloth, const std::vector<Vec3>& normals,
                         const std::vector<float>& strain, std::vector<float>& out);

} // namespace clothtear::app
