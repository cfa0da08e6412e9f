// The tear phase: the scan's candidates go to the tear module (tear.h), the only code that changes
// the cloth's topology; particles it duplicates keep following the drivers of their originals.
#include "phases.h"

#include <algorithm>

namespace clothtear {

void phaseTear(const StepContext& ctx, Cloth& cloth, StepState& state) {
    std::vector<std::pair<Index, Index>> copies;
    TearContext tear{ctx.settings->tear, ctx.time, ctx.tearLog, &copies};
    tearSprings(cloth, state.tearCandidates, tear);
    driversFollowCopies(*ctx.drivers, copies);
}

void driversFollowCopies(std::vector<Driver>& drivers, const std::vector<std::pair<Index, Index>>& copies) {
    for (const auto& [original, copy] : copies)
        for (Driver& d : drivers)
            if (std::find(d.particles.begin(), d.particles.end(), original) != d.particles.end())
                d.particles.push_back(copy);
}

} // namespace clothtear
