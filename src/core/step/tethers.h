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
//
// Three sets (issue 12): to the nearest anchor, and to each of the two anchors farthest apart (the
// ends of a pinned edge, the two pinned corners). One anchor bounds a particle's distance from one
// point only: a 6 m cloth pinned on its left edge hung each particle from the pin of its own row,
// and the cloth folded down under it, stretched along paths to the pins above, which only the
// passes could pull back (4 x the depth and more: strain 0.109 at 65 a side and 0.112 at 129 after
// 5 s, 311 and 1,260 sub-steps of the last second out of passes, 18 and 246 ms a frame on one
// thread). With the tethers to the top and bottom pins too, it settles at the limit in every
// sub-step, at 3.6 and 52 ms (bench/README.md, "Tethers to the ends of the pins"). Kim et al.
// attach a particle to several anchors for the same reason. The span's ends are chosen at rest,
// so they do not depend on the resolution. Cost at rest: two more checks a particle, about 9 % of
// a 128 x 128 sub-step.
#pragma once
#include "clothtear/cloth.h"
#include "step_state.h"

#include <vector>

namespace clothtear {

// Rebuilds the tether sets and the particle-to-spring table of `cache` for `cloth`: anchors are the
// particles with anchor[p] != 0 (pinned and not moved by a driver). Particles that no anchor
// reaches through structural springs get no tether. Sizes the work arrays.
void buildLimitCache(const Cloth& cloth, const std::vector<uint8_t>& anchor, LimitCache& cache);
// LimitCache::regionBin, for the Gauss-Seidel passes on several threads (limit.cpp, regionPasses);
// buildLimitCache empties it.
void buildRegionBins(const Cloth& cloth, LimitCache& cache);

// Marks in `set.cut` every particle whose tether path runs through a particle in `seeds`: their
// tethers must not pull this sub-step (a spring on the path is tearing).
void markTethersThrough(TetherSet& set, const std::vector<Index>& seeds);

} // namespace clothtear
