// Non-finite detection at the phase boundaries of a sub-step (step.cpp): which value went
// NaN or infinite first, named by what it is and its index, so a blow-up is traced to the phase
// that made it instead of being found a frame later somewhere in the cloth.
#pragma once
#include "clothtear/world.h"
#include "step_state.h"

#include <string>
#include <vector>

namespace clothtear {

// The first non-finite value of the cloth's positions and velocities, the balls and (when given)
// the per-thread force buffers of the spring and wind phases (with the spring groups' arrays when
// the spring phase wrote them): "" when all are finite, else e.g. "particle 41: velocity (nan, 0,
// 0)" or "particle 7: force (inf, 0, 0)".
std::string findNonFinite(const Cloth& cloth, const std::vector<Ball>& balls, const ThreadBuffers* forces);

} // namespace clothtear
