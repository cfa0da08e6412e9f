// Peers (mode `peers`): Bullet's soft-body cloth, built only when Bullet is found (bullet/).
#pragma once
#include <string>

namespace clothtear::bench {

struct PeerResult {
    bool available = false;
    std::string note;        // why not available, or the version
    double msPerSubstep = 0; // fastest of the repetitions
    double meanStretch = 0;  // mean (len - rest) / rest over the links, at rest
    double worstStretch = 0; // largest (len - rest) / rest
    size_t links = 0;
};

// Bullet soft-body cloth: an n x n patch of 2 m x 2 m (btSoftBodyHelpers::CreatePatch with
// diagonals), top row of nodes fixed, the same total mass as ours (0.8 kg), randomizeConstraints(),
// 10 sub-steps per 1/60 s frame; settled `settleSeconds`, then `measureSubsteps` sub-steps timed.
PeerResult runBulletCloth(int n, double settleSeconds, int measureSubsteps, int repetitions);

} // namespace clothtear::bench
