// A coarser index buffer for a cloth seen from far (issue 15 goal 5). llvmpipe pays for every
// triangle it sets up: a 256 x 256 cloth (130 k triangles) filling a third of a 1280 x 720 window
// gives each triangle about two pixels, and its frame costs about 27 ms of draw and swap where a
// 128 x 128 cloth of the same size costs 14. Where the mesh is a regular grid in UV space, every
// block of 2 x 2 grid cells that is intact is drawn as two triangles over its corners: the same
// render vertices (positions, smoothed normals, UVs), a quarter of the triangles. No GL here.
//
//   a block, lattice points (i, j) = 0..2        drawn coarse            beside a block drawn fine
//   02 --- 12 --- 22                          02 ----------- 22        02 --- 12 --- 22
//    |  /   |  /   |                           |          /   |         | \     |     / |
//   01 --- 11 --- 21                           |       /      |        01 -- 11       |
//    |  /   |  /   |                           |    /         |         | /     \     |
//   00 --- 10 --- 20                          00 ----------- 20        00 ----------- 20
//
// A block is intact when its eight triangles are all there, every corner on a lattice point, and each
// lattice point one render vertex (a tear gives one side its own copies, a basic tear adds midpoints:
// either leaves the block drawn as it is). Where an intact block borders a block drawn fine, the side
// they share keeps its midpoint (a fan round the block's centre) so that no crack opens at the
// T-junction.
#pragma once
#include "render_mesh.h"

#include <cstdint>
#include <vector>

namespace clothtear::app {

// Indices into mesh's render vertices (RenderMesh::rebuild of the same cloth) that draw the whole
// cloth with the intact blocks coarse. Empty when no block is intact (an irregular or OBJ mesh).
std::vector<uint32_t> coarseGridIndices(const Cloth& cloth, const RenderMesh& mesh);

// The coarse indices are drawn when a grid cell at the cloth's nearest point spans fewer than this
// many pixels (a coarse block under twice that). The 2 m curtain at 256 x 256, framed by the start
// camera in a 720-pixel window, has cells of about 2.3 pixels; drawn coarse, 60 pixels of the cloth
// differ from the fine image by more than 2 levels (its outline and the cut), at 128 x 128 (4.6
// pixels) it is drawn fine.
inline constexpr float kCoarseBelowPixels = 3.f;

// Pixels that one metre spans, seen face on at `distance` m from the eye, in a window `heightPixels`
// tall with vertical field of view `fovY` (rad).
float pixelsPerMetre(float distance, float fovY, float heightPixels);

} // namespace clothtear::app
