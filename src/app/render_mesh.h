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

// ---- Torn edges and their fringe of loose threads -------------------------------------------------
//
// A tear (or the knife) separates two triangles along an edge by giving one side its own copies of
// the particles, which keep the rest positions of the originals: a torn edge is a border edge (one
// triangle) whose rest-space segment is also another border edge's, its other side. The cloth's own
// hem has no such twin. (A torn edge whose other side was deleted with its piece counts as hem.)
//
//        rest space              a torn edge: two border springs, the same rest segment
//   +-----+-----+               +-----+-----+
//   |   / |   / |               |   / |   / |       <- one side's copy (a, b)
//   | /   | /   |     tear      | /   | /   |
//   +-----+-----+    ----->     +-----+-----+
//   |   / |   / |               +-----+-----+       <- the other side's copy (a', b')
//   | /   | /   |               |   / |   / |
//   +-----+-----+               | /   | /   |
//                               +-----+-----+
// Returns the structural springs that are torn edges, in spring order.
std::vector<Index> findTornEdges(const Cloth& cloth);

// The fringe: along each torn edge a strip in the plane of its triangle, reaching out of the cloth by
// `reach` metres, on which the fragment shader (shaders/fringe.frag.glsl) draws short threads with
// an alpha test: one thread per woven thread that crosses the edge (kWovenThreads per texture unit,
// so the fringe follows the weave's scale on any mesh), each of its own length and slant.
//
//   a' ------------- b'      outer edge: a, b + reach x outward (in the triangle's plane, away from c)
//   | | |  |  | | |  |       the threads, alpha-tested
//   a =============== b      the torn edge
//          c                 the triangle's third corner
struct FringeMesh {
    struct Edge {
        Index a, b, c;     // the edge's particles and the triangle's third corner
        float uv[4];       // the corners' texture coordinates at a and b (u, v, u, v)
        float threads[2];  // thread coordinate at a and at b: u or v (the larger change) x threads per uv
        float reach;       // m, the longest thread: 1.4 thread spacings of this edge
    };
    std::vector<Edge> edges;
    uint64_t revision = ~uint64_t(0); // cloth.topologyRevision these were built from
    size_t particleCount = 0;

    bool stale(const Cloth& cloth) const {
        return revision != cloth.topologyRevision || particleCount != cloth.particleCount();
    }
    void rebuild(const Cloth& cloth, float threadsPerUv);
};

// Per fringe vertex: position (3), normal (3), uv (2), thread coordinate (1), across (1: 0 at the
// edge, 1 at the outer edge). Four vertices per edge (a, b, b', a'); fringeIndices gives two
// triangles per edge, wound as the cloth's triangle so that its front is the cloth's front.
inline constexpr int kFringeFloats = 10;
void fillFringeVertices(const FringeMesh& fringe, const Cloth& cloth, const std::vector<Vec3>& normals,
                        std::vector<float>& out);
void fringeIndices(size_t edges, std::vector<uint32_t>& out);

} // namespace clothtear::app
