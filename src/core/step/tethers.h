// Long-range attachments ("tethers") for the length limit: each free particle may not be farther
// from the pinned particle it hangs from than (1 + max_stretch) times the rest length of a path of
// springs between them. Kim, Chentanez, Mueller, "Long Range Attachments - A Method to Simulate
// Inextensible Clothing in Computer Games", SCA 2012.
//
// Why: the averaged Jacobi limit moves a correction about one spring per pass, so a 256-row
// curtain held by a dozen passes per sub-step sags far past the limit (strain 0.4-0.6 at rest,
// past the tear threshold). A tether carries the anchor's position to every particle in one pass.
//
// Only where the Jacobi passes alone cannot hold the cloth. Gravity moves every particle g dt^2
// per sub-step and the passes carry a correction about one spring per pass, so how far the cloth
// sags past the limit grows with the sag index  D^2 g dt^2 / (iterations h)  (D: springs from the
// anchors to the farthest particle, h: mean spring rest length). Measured with 12 passes and
// 10 sub-steps of 1/600 s, the 2 m curtain hangs at strain 0.12 at 64x64 (index 0.29), 0.16 at
// 128x128 (2.3) and 0.37 at 256x256 (19), past the tear threshold; the tearing scenes' 6 m cloth
// at 48x48 has index 0.04 and hangs within the limit. Above kTetherSagIndex the tethers are on;
// below, the cloth behaves as the tearing scenes were tuned (tethers also make a cloth stiffer
// against impacts than the unconverged passes do).
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

inline constexpr float kTetherSagIndex = 0.2f;

// The sag index of a cloth D springs deep (see above).
inline float sagIndex(uint32_t depth, float gravity, float dt, int iterations, float meanRest) {
    if (iterations <= 0 || !(meanRest > 0.f)) return 0.f;
    return float(depth) * float(depth) * gravity * dt * dt / (float(iterations) * meanRest);
}

// Rebuilds the tethers and the particle-to-spring table of `cache` for `cloth`: anchors are the
// particles with anchor[p] != 0 (pinned and not moved by a driver). Particles that no anchor
// reaches through structural springs get no tether. Sizes the work arrays.
void buildLimitCache(const Cloth& cloth, const std::vector<uint8_t>& anchor, LimitCache& cache);

// Marks in `cut` (size = particle count) every particle whose tether path runs through a particle
// in `seeds`: their tethers must not pull this sub-step (a spring on the path is tearing).
void markTethersThrough(const LimitCache& tethers, const std::vector<Index>& seeds, std::vector<uint8_t>& cut);

} // namespace clothtear
