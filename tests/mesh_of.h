// Tiny hand-built meshes for tests (shared by the limit and tear-mode tests): UVs taken
// from the rest positions' x and y.
#pragma once
#include "clothtear/mesh.h"

#include <array>
#include <utility>
#include <vector>

namespace clothtear::test {

inline MeshData meshOf(std::vector<Vec3d> positions, std::vector<std::array<Index, 3>> triangles) {
    MeshData m;
    m.positions = std::move(positions);
    m.triangles = std::move(triangles);
    for (const auto& t : m.triangles)
        m.cornerUVs.push_back({m.positions[t[0]].head<2>(), m.positions[t[1]].head<2>(), m.positions[t[2]].head<2>()});
    return m;
}

// The unit square in the xy plane, of two triangles: (0,0) (1,0) (1,1) and (0,0) (1,1) (0,1).
inline MeshData unitSquare() { return meshOf({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}}); }

} // namespace clothtear::test
