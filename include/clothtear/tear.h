// Tearing (Onal 3.2-3.3): basic tear, weak points, one-point connections. The only module that
// changes cloth topology; it runs between the other phases and emits one TearEvent per tear.
#pragma once
#include "clothtear/cloth.h"
#include "clothtear/settings.h"
#include "clothtear/tear_events.h"

#include <algorithm>
#include <string>
#include <vector>

namespace clothtear {

struct TearCandidate {
    Index spring;  // structural spring index at scan time
    float strain;  // (len - rest) / rest at scan time
};

// The one rule for the strain at which a structural spring tears (Onal 3.2.1-3.2.3), read by the
// strain scan (which lists and exempts candidates) and by the tear module (which picks the mode).
// Springs touching a hem (kHem: an edge the pin mode pinned) tear at tear.seam_strength x
// tear.threshold, whatever else they touch: a rip that reaches the hem stops there (issue 13).
// Springs touching a weak point or a one-point connection tear from the lower of those thresholds,
// or from tear.threshold if that is lower still; any other spring from tear.threshold.
inline float weakEndThreshold(const TearSettings& T) { return std::min(T.weakThreshold, T.onePointThreshold); }
inline float hemThreshold(const TearSettings& T) { return T.threshold * std::max(1.f, T.seamStrength); }
inline float tearStrainFor(const TearSettings& T, bool weakEnd, bool hemEnd = false) {
    if (hemEnd) return hemThreshold(T);
    return weakEnd ? std::min(weakEndThreshold(T), T.threshold) : T.threshold;
}

struct TearContext {
    const TearSettings& settings;
    double time;
    TearLog* log;
    // Out: (original, copy) for every particle duplicated by a weak-point or one-point tear, so the
    // caller can let copies follow what held the original (drivers, tools). May be null.
    std::vector<std::pair<Index, Index>>* copies = nullptr;
};

// Processes candidates most-strained first, up to settings.maxPerStep tears. Candidates are re-checked
// before each tear (earlier tears move particles and renumber springs). Returns the number of tears.
int tearSprings(Cloth& cloth, std::vector<TearCandidate>& candidates, const TearContext& ctx);

// Forces one tear of spring s whatever its strain (topology fuzzing, the notch of the tension scene).
// Picks the mode the strain scan would: weak-point tear when an end is weak, else basic tear.
bool forceTear(Cloth& cloth, Index spring, const TearContext& ctx);

// Checks every topology invariant (see validate.cpp). Returns "" or the first violation found.
std::string validateCloth(const Cloth& cloth, double expectedArea = -1, double expectedUvArea = -1);

} // namespace clothtear
