// Long-range attachments ("tethers") for the length limit: each free particle may not be farther
// from the pinned particle it hangs from than (1 + max_stretch) times the rest length of a path of
// springs between them. Kim, Chentanez, Mueller, "Long Range Attachments - A Method to Simulate
// Inextensible Clothing in Computer Games", SCA 2012.
//
// Why: the averaged Jacobi limit moves a correction about one spring per pass, so a 256-row
// curtain held by a dozen passes per sub-step sags far past the limit (strain 0.4-0.6 at rest,
// past the tear threshold). A tether carries the anchor's position to every particle in one pass.
//
// Always on with the limit (issue 12). They were on only where a sag index said the passes alone
// could not hold the cloth; measured with the full-stiffness springs and the Gauss-Seidel limit
// (bench/README.md, "Does the cloth hold?"), without them a 2 m cloth pinned at its corners or
// its left edge hung at strain 0.11-0.15 and a 6 m one at up to 0.29 (limit 0.10), with them
// every grid case but the 6 m cloth pinned left settles at the limit.
//
// A tether is implied by the spring limits (a path of springs each at most (1 + s) rest long spans
// at most (1 + s) times the path's rest length), so it never pulls a cloth whose springs are all
// within the limit; it only speeds up convergence. Paths are breadth-first (fewest springs, then
// shortest) rather than exact geodesics: any path gives a valid tether, a longer one a looser one.
#pragma once
#include "clothtear/cloth.h"
#include "step_state.h"

#include <vector>

namespace clothtear {

// Rebuilds the tethers and the particle-to-spring table of `cache` for `cloth`: anchors are the
// particles with anchor[p] != 0 (pinned and not moved by a driver). Particles that no anchor
// reaches through structural springs get no tether. Sizes the work arrays.
void buildLimitCache(const Cloth& cloth, const std::vector<uint8_t>& anchor, LimitCache& cache);

// Marks in `cut` (size = particle count) every particle whose tether path runs through a particle
// in `seeds`: their tethers must not pull this sub-step (a spring on the path is tearing).
void markTethersThrough(const LimitCache& tethers, const std::vector<Index>& seeds, std::vector<uint8_t>& cut);

} // namespace clothtear
