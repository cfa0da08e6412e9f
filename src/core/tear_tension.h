// The direction in which the fabric round a tear tip is stretched most: the tension axis a
// weak-point tear cuts across (tear.cpp, weakTear, step 4). Internal to the core.
#pragma once
#include "clothtear/cloth.h"

#include <span>

namespace clothtear {

// The principal direction (world space, unit) of the tensile part of the fabric's strain within
// `radius` (metres, at rest) of tip p: for every triangle joined to p's fan whose rest centroid lies
// that close (the fan's own triangles always), the Green strain's positive principal stretches,
// pushed forward to the triangle as it is now and summed by rest area. Compression does not steer a
// tear. Zero, so that the caller keeps the thesis's axis (the tense spring), when radius is not
// positive, when a held particle (a pin or the hand's patch, kPinned) lies in that fabric (there the
// stretch is what the hold imposes, and its average mixes held and free cloth), or when no single
// direction is stretched most.
Vec3 fabricTensionAxis(const Cloth& cloth, Index p, std::span<const Index> fanTriangles, float radius);

} // namespace clothtear
