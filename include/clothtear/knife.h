// The knife (issue 14, Onal 5.2 "using a knife for cutting a cloth"): cuts the cloth along a stroke
// drawn in its rest (material) space, so a cut follows the material whatever shape the cloth is in.
//
// A stroke is a polyline of points (u, v) in metres in a mesh's knifeFrame: its own plane (meshFrame,
// mesh.h), u along its "right", v along its "up", from the middle of its extent. For the built-in
// grid and irregular meshes u = x and v = y of the rest positions; for an OBJ the frame of its own
// plane. A mesh that is not flat is cut where its projection on that plane meets the stroke (every
// layer it folds over there).
//
// Topology changes only through the tear module's own operations (src/core/tear_topology.h): the
// springs the stroke crosses are split at the crossing (splitSpring, the basic tear's split without
// the separation), which makes the stroke a chain of mesh edges; the cloth is then separated along
// those edges by detaching triangle groups from their particles (detachGroup, the weak-point and
// one-point machinery). UVs, rest areas, masses, weights, bend springs and weak/hinge flags are kept by
// the same bookkeeping as a tear (refreshAround): no rest or UV area is ever lost (Onal 3.3).
#pragma once
#include "clothtear/cloth.h"
#include "clothtear/mesh.h"
#include "clothtear/tear.h"

#include <string>
#include <vector>

namespace clothtear {

struct CutResult {
    std::string error;          // "" or why the stroke was refused (then nothing changed)
    size_t springsCut = 0;      // joined edges along the stroke opened into two walls (one TearEvent each)
    size_t springsSplit = 0;    // springs split where the stroke crosses them (refinement, not yet a cut)
    size_t particlesAdded = 0;  // new particles: crossing points and the copies that separate the sides
    bool ok() const { return error.empty(); }
};

// The frame strokes are given in: meshFrame(points), its origin moved to the middle of the points'
// extent along right and up (so u, v run over [-width/2, width/2] x [-height/2, height/2]).
MeshFrame knifeFrame(const std::vector<Vec3d>& meshPoints);

// Why a stroke is refused, or "": fewer than two points, a coordinate that is not finite or beyond
// +-kMaxCoordinate, or no length at all.
std::string checkStroke(const std::vector<Vec2d>& stroke);

// Cuts `cloth` along `stroke` (points in `frame`, see above), segment by segment; between phases
// only (World::cut). Every joined structural spring on the stroke is separated, so the material on
// the two sides is no longer joined across it:
//   - a spring the stroke crosses is split at the crossing; a crossing within a tenth of a spring's
//     length of its end (or on a spring too short to split, cloth.minSplitRest) goes through that end
//     particle instead, so no sliver triangle or very short, stiff spring is made;
//   - a stroke through a particle splits the particle along the stroke: its fan is divided by the
//     stroke's two edges there and one side gets a copy of the particle (the weak-point rule,
//     Onal 3.2.2); a one-point connection on the stroke is cut through (3.2.3);
//   - a stroke along an existing edge opens that edge; along a border or a torn edge it does nothing;
//   - a stroke's end or corner inside a triangle becomes a particle there, so consecutive strokes
//     join up; where a cut ends inside the cloth its end is a weak point (a tear tip), as a tear's.
// A stroke that misses the cloth changes nothing (0 springs). One TearEvent of mode Knife per
// spring cut (ctx.log), copies made reported in ctx.copies; validated as a tear is
// (validateAfterChange). A refused stroke (checkStroke) changes nothing.
CutResult cutAlong(Cloth& cloth, const MeshFrame& frame, const std::vector<Vec2d>& stroke, const TearContext& ctx);

} // namespace clothtear
