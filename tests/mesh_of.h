// Tiny hand-built meshes for tests (shared by the limit and tear-mode tests): UVs taken
// from the rest positions' x and y.
#pragma once
#include "clothtear/mesh.h"
#include "clothtear/world.h"

#include <gtest/gtest.h>

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

// `w` as the unit square with no gravity and no ground, every particle pinned, and the corner at
// (1, 0) moved along x so that the bottom edge has strain e (no other structural spring comes near a
// threshold: the right edge stretches by less than e / 4). The limit cannot pull two pinned ends
// together, so the load lasts. The caller sets what it watches before stepping.
inline void stretchedPinnedSquare(World& w, double e) {
    w.settings.gravity = GravitySettings{0.f, 0.f, 0.f};
    w.settings.collision.ground = false;
    w.settings.cloth.pin = PinMode::None;
    EXPECT_EQ(w.rebuild(unitSquare()), "");
    for (Index p = 0; p < w.cloth.particleCount(); ++p) w.cloth.setPinned(p, true);
    for (Index p = 0; p < w.cloth.particleCount(); ++p)
        if (w.cloth.rest[p] == Vec3d(1, 0, 0)) w.cloth.x[p].x() = float(1.0 + e);
}

} // namespace clothtear::test
