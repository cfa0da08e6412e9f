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
    int positionIterations = 0; // what ran (Bullet's default when 0 was asked)
};

// Bullet soft-body cloth: an n x n patch of 2 m x 2 m (btSoftBodyHelpers::CreatePatch with
// diagonals), top row of nodes fixed, the same total mass as ours (0.8 kg), randomizeConstraints(),
// `substepsPerFrame` sub-steps per 1/60 s frame (10 unless asked); settled `settleSeconds`, then
// `measureSubsteps` sub-steps timed.
// positionIterations: Bullet's m_cfg.piterations (its link solver passes per sub-step); 0 keeps
// Bullet's default (1). Raising it is how a Bullet user makes the cloth stretch less.
PeerResult runBulletCloth(int n, double settleSeconds, int measureSubsteps, int repetitions,
                          int positionIterations = 0, int substepsPerFrame = 10);

} // namespace clothtear::bench
