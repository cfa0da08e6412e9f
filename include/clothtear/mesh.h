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
