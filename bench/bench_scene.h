// Benchmark scenes: the `curtain` at a given resolution with the scene's default material, settled
// until it hangs at rest. Shared by every case in bench_step.cpp.
//
// The default material (stretch 60 N/m) is far stiffer than explicit integration allows at 128x128
// and above with 10 sub-steps per 1/60 s frame; time.stability_guard (on by default) caps each
// spring to its stable stiffness and the Provot limit carries the rest of the load. stability()
// reports how far the *requested* material is past the explicit limit, for the benchmark label.
#pragma once
#include "clothtear/world.h"

#include <string>

namespace clothtear::bench {

// What makes explicit springs stable at a sub-step dt (semi-implicit Euler, per particle p):
//   a_p = dt^2 * sum(k_i) / m_p,   b_p = dt * sum(kd_i) / m_p   over the springs touching p.
// A mode with stiffness w^2 and damping g is stable when w^2 dt^2 + 2 g dt < 4; Gershgorin bounds
// w^2 <= 2 sum(k)/m and g <= 2 sum(kd)/m, so every mode is stable when a/2 + b < 1.
struct StabilityReport {
    double stiffnessTerm = 0; // max over free particles of a_p
    double dampingTerm = 0;   // max over free particles of b_p
    double margin() const { return 0.5 * stiffnessTerm + dampingTerm; } // < 1: stable
};
StabilityReport stability(const World& world); // of the material as set, before the guard

struct CurtainOptions {
    int resolution = 128;      // particles per side
    bool tearing = true;       // tear.enabled (the strain scan runs when true)
    double settleSeconds = 1.5; // simulated seconds before measuring
};

// The settled curtain (cached per resolution: settling once at 256x256 takes seconds). The copy
// returned has its profile reset and tearing set as asked.
World settledCurtain(const CurtainOptions& options);

// Largest (len - rest) / rest over structural springs.
float maxStructuralStrain(const World& world);

// Human-readable description of the material chosen for a resolution (for the benchmark context).
std::string describeMaterial(const World& world);

} // namespace clothtear::bench
