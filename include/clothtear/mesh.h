// Mesh sources: a triangle soup with per-corner UVs that the cloth is built from.
#pragma once
#include "clothtear/types.h"

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace clothtear {

// Rest geometry of a cloth: vertex positions in metres (the unstressed shape) and triangles with
// their texture coordinates stored per corner (Onal 3.3), so a cut never needs per-vertex UVs.
struct MeshData {
    std::vector<Vec3d> positions;
    std::vector<std::array<Index, 3>> triangles;
    std::vector<std::array<Vec2d, 3>> cornerUVs; // one per triangle corner, same order as triangles
};

// W x H particles on a width x height rectangle in the x-y plane (y up, top edge at y = height/2,
// centred on x = 0). Quads are split along alternating diagonals (a "union jack" pattern) so the
// grid has no preferred tear direction.
MeshData makeGridMesh(int particlesX, int particlesY, double width, double height);

// Irregular triangulation of the same rectangle: interior vertices of the grid are jittered by up to
// `jitter` x spacing (border vertices slide only along their border) and each quad is split along its
// shorter diagonal, giving non-uniform triangles of varied shape and size. Deterministic for a seed.
MeshData makeIrregularMesh(int particlesX, int particlesY, double width, double height, double jitter,
                           uint32_t seed);

// OBJ import (v, vt, f; polygons are fan-triangulated). Faces without vt get planar UVs from the
// bounding box. Errors name the file and line. Files over 256 MiB are refused before reading.
Result<MeshData> loadObj(const std::string& path);
// The same from text in memory (the fuzzer, generated meshes); `source` stands for the file name.
Result<MeshData> parseObj(std::string_view text, const std::string& source);
// Writes a MeshData as OBJ with one vt per triangle corner.
bool saveObj(const MeshData& mesh, const std::string& path);

// The frame a setup reads a mesh in (pin modes, the pull's hand, the ball's aim): the mesh's own plane,
// fitted through its points, with "up" the in-plane direction nearest world +y and "right" = up x
// normal. A mesh lying flat (a plane exported from a modeller) has no in-plane +y: its far edge (-z)
// is its top, as seen from a camera on +z. The normal faces +z for an upright mesh and +y for a flat
// one. Axes within 1e-9 of a world axis are snapped to it, so the built-in meshes (x-y plane) get
// exactly x, y and z, and u = x, v = y about their centre.
struct MeshFrame {
    Vec3d centre = Vec3d::Zero(); // the mean of the points
    Vec3d right = Vec3d::UnitX(), up = Vec3d::UnitY(), normal = Vec3d::UnitZ();
    double minU = 0, maxU = 0, minV = 0, maxV = 0; // the points' extent along right (u) and up (v)

    double u(const Vec3d& p) const { return (p - centre).dot(right); }
    double v(const Vec3d& p) const { return (p - centre).dot(up); }
    Vec3d at(double u, double v) const { return centre + u * right + v * up; }
    double width() const { return maxU - minU; }
    double height() const { return maxV - minV; }
};
MeshFrame meshFrame(const std::vector<Vec3d>& points);

// What every mesh source is held to (checkMesh), so that the step's float state and the tear code
// can represent the cloth: positions within +-kMaxCoordinate (float keeps ~1 cm there), texture
// coordinates within +-kMaxUv, no edge shorter than kMinEdge (a spring's rest length as a float), and
// no triangle whose area, in space or in UV, is below 1e-12 of its longest squared edge.
inline constexpr double kMaxCoordinate = 1e5; // m
inline constexpr double kMaxUv = 1e6;
inline constexpr double kMinEdge = 1e-7; // m

// Checks that indices are in range, coordinates finite and within the limits above, and no
// triangle is degenerate in space or in UV. Returns an empty string when valid; `source` prefixes
// the message.
std::string checkMesh(const MeshData& mesh, const std::string& source);

} // namespace clothtear
