// The stability guard's estimate of the largest stable explicit sub-step (world.h,
// stableStepEstimate), from each particle's springs.
//
// Semi-implicit Euler (and Verlet, the same recurrence) on a mode of stiffness w^2 and damping g is
// stable while w^2 dt^2 + 2 g dt < 4. Gershgorin's theorem bounds every mode of the linearized
// spring network through the rows of M^-1 K: w^2 <= 2 sum(k) / m_p and g <= 2 sum(kd) / m_p over
// the springs of particle p, so every mode is stable when, for every free particle,
//   (A dt^2) / 2 + B dt < 1,   A = sum(k) / m_p,  B = sum(kd) / m_p,
// i.e. dt < (sqrt(B^2 + 2 A) - B) / A. The stiffest springs on the lightest particle decide it.
// Forward Euler has no stable step for an undamped mode; the estimate is the same and the
// stability map (bench/README.md) shows how far it is off for that method.
#include "clothtear/world.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace clothtear {

void springSumsPerParticle(const Cloth& cloth, const MaterialSettings& m, std::vector<double>& k,
                           std::vector<double>& kd) {
    k.assign(cloth.particleCount(), 0.0);
    kd.assign(cloth.particleCount(), 0.0);
    auto add = [&](const std::vector<Spring>& springs, double ks, double kds) {
        for (const Spring& s : springs)
            for (Index p : {s.a, s.b}) {
                k[p] += ks * s.weight;
                kd[p] += kds * s.weight;
            }
    };
    add(cloth.springs, m.stretchStiffness, m.stretchDamping);
    add(cloth.bends, m.bendStiffness, m.bendDamping);
}

double stableStepEstimate(const Cloth& cloth, const Settings& settings, double lightMassFraction) {
    if (!isExplicit(settings.time.integrator))
        return std::numeric_limits<double>::infinity();
    const size_t n = cloth.particleCount();
    std::vector<double> k, kd;
    springSumsPerParticle(cloth, settings.material, k, kd);
    std::vector<std::pair<double, double>> stepAndMass; // per free particle with springs
    stepAndMass.reserve(n);
    double freeMass = 0;
    for (Index p = 0; p < n; ++p) {
        const double w = cloth.invMass[p];
        if (w == 0.0)
            continue;
        const double A = k[p] * w, B = kd[p] * w;
        double step = std::numeric_limits<double>::infinity();
        if (A > 0)
            step = (std::sqrt(B * B + 2 * A) - B) / A;
        else if (B > 0)
            step = 1.0 / B;
        stepAndMass.emplace_back(step, 1.0 / w);
        freeMass += 1.0 / w;
    }
    if (stepAndMass.empty())
        return std::numeric_limits<double>::infinity();
    auto lightest = std::min_element(stepAndMass.begin(), stepAndMass.end());
    if (!(lightMassFraction > 0))
        return lightest->first;
    // The step every particle meets but the ones that need a shorter one and together hold at most
    // lightMassFraction of the mass.
    std::sort(stepAndMass.begin(), stepAndMass.end());
    double below = 0;
    for (const auto& [step, mass] : stepAndMass) {
        below += mass;
        if (below > lightMassFraction * freeMass)
            return step;
    }
    return stepAndMass.back().first;
}

} // namespace clothtear
