// The tear phase: the scan's candidates go to the tear module (tear.h), the only code that changes
// the cloth's topology; particles it duplicates keep following the drivers of their originals.
#include "phases.h"

#include <algorithm>

namespace clothtear {

void phaseTear(const StepContext& ctx, Cloth& cloth, StepState& state) {
    std::vector<std::pair<Index, Index>> copies;
    TearContext tear{ctx.settings->tear, ctx.time, ctx.tearLog, &copies};
    tearSprings(cloth, state.tearCandidates, tear);
    // A particle duplicated by a tear keeps following whatever drove the original.
    for (const auto& [original, copy] : copies)
        for (Driver& d : *ctx.drivers)
            if (std::find(d.particles.begin(), d.particles.end(), original) != d.particles.end())
                d.particles.push_back(copy);
}

} // namespace clothtear
