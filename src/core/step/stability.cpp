// The stability guard's estimate of the largest stable explicit sub-step (world.h,
// stableStepEstimate), from each particle's springs.
//
// Semi-implicit Euler (and Verlet, the same recurrence) on a mode of stiffness w^2 and damping g is
// stable while w^2 dt^2 + 2 g dt < 4. Gershgorin's theorem bounds every mode of the linearized
// spring network through the rows of M^-1 K: w^2 <= 2 sum(k) / m_p and g <= 2 sum(kd) / m_p over
// the springs of particle p, so every mode is stable when, for every free particle,
//   (A dt^2) / 2 + B dt < 1,   A = sum(k) / m_p,  B = sum(kd) / m_p,
// i.e. dt < (sqrt(B^2 + 2 A) - B) / A. The stiffest springs on the lightest particle decide it.
// A nonlinear law (material.model = kes) enters with its largest tangent stiffness over the strains
// the step lets a spring reach (kesStrainRange in kes.h), so the estimate holds wherever it goes.
// Forward Euler has no stable step for an undamped mode; the estimate is the same and the
// stability map (bench/README.md) shows how far it is off for that method. With kes, forward Euler
// damps the law's modes (Rayleigh, kesRayleighTime in kes.h) and the law's springs and hinges count
// kesGuardWeight = 5 times their tangent here: the damping's share of the sum, and (omega dt)^2 <= 0.8
// where forward Euler with that damping needs omega dt <= 1.
#include "clothtear/kes.h"
#include "clothtear/world.h"
#include "spring_caps.h"
#include "step_context.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace clothtear {

// The stiffness each kind of spring asks for, per unit weight: the linear material's, or with
// material.model = kes the tensile law's largest tangent over the strains the step lets a spring
// reach (kesStrainRange), and no bend-shear springs (hinges instead, added by addHinges).
AskedStiffness structuralAsked(const Settings& s) {
    if (s.material.model == MaterialModel::Kes)
        return {kesGuardWeight(s) * kesMaxTangent(kesLawSI(s.material), kesStrainRange(s)), s.material.stretchDamping};
    return {s.material.stretchStiffness, s.material.stretchDamping};
}

namespace {
// kes: each hinge adds to the Gershgorin row sums of its four corners (kesHingeStiffness, kes.h,
// times kesGuardWeight); hinges have no damping of their own.
void addHinges(const Cloth& cloth, const Settings& s, std::vector<double>& k) {
    if (s.material.model != MaterialModel::Kes) return;
    const KesLaw law = kesLawSI(s.material);
    const double weight = kesGuardWeight(s);
    for (Index b = 0; b < cloth.bends.size(); ++b) {
        const HingeGeometry h = hingeOf(cloth, b);
        const double kh = weight * kesHingeStiffness(law, h);
        for (Index p : {h.c, h.d, h.a, h.e}) k[p] += kh;
    }
}
} // namespace

void springSumsPerParticle(const Cloth& cloth, const Settings& settings, std::vector<double>& k,
                           std::vector<double>& kd) {
    const MaterialSettings& m = settings.material;
    k.assign(cloth.particleCount(), 0.0);
    kd.assign(cloth.particleCount(), 0.0);
    auto add = [&](const std::vector<Spring>& springs, double ks, double kds) {
        for (const Spring& s : springs)
            for (Index p : {s.a, s.b}) {
                k[p] += ks * s.weight;
                kd[p] += kds * s.weight;
            }
    };
    const AskedStiffness asked = structuralAsked(settings);
    add(cloth.springs, asked.stiffness, asked.damping);
    if (m.model == MaterialModel::Linear) add(cloth.bends, m.bendStiffness, m.bendDamping);
    addHinges(cloth, settings, k);
}

namespace {

// Which step stepsAndMasses gives each particle.
enum class StepBound {
    Stable,     // the largest stable step (Gershgorin, above)
    Budget,     // the guard's: within its budget (spring_caps.h, kParticleBudget, with the air
                // drag's share), where guardParticleBudget (springs.cpp) scales nothing
    SpringCaps, // the guard's with per-spring caps (the kes law, or a ball near or a hand moving,
                // step.cpp): the Gershgorin step, no longer than the one at which none of the
                // particle's springs needs a cap
};

// Per free particle: its step (StepBound) and its mass. At the Gershgorin step alone the per-spring
// caps (made for a particle with ~8 springs) softened a 33 x 33 curtain by a third, hence their own
// step; it is 1.5-1.9 x shorter than the budget's (76 instead of 48 sub-steps a frame at 128 x 128)
// and kept where the ball and drag outcomes were measured and are tested (bench/README.md, "The
// guard's step from the particle budget").
using StepList = std::vector<std::pair<double, double>>;
struct ParticleSteps {
    StepList steps;     // with the springs' damping, or without it where dampingFree asked
    StepList freeSteps; // with alsoDampingFree: the same particles' steps without the damping
};
ParticleSteps stepsAndMasses(const Cloth& cloth, const Settings& settings, StepBound bound, bool dampingFree,
                             bool alsoDampingFree = false) {
    const MaterialSettings& m = settings.material;
    const size_t n = cloth.particleCount();
    std::vector<double> k, kd;
    springSumsPerParticle(cloth, settings, k, kd);
    // Damping taken implicitly (time.damping) is stable at any step: only the stiffness bounds it
    // (integrate.cpp).
    if (dampingFree) std::fill(kd.begin(), kd.end(), 0.0);
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<double> springStep(n, inf), springStepFree(alsoDampingFree ? n : 0, inf);
    if (bound == StepBound::SpringCaps) {
        // A particle's step is the shortest of its springs', sqrt(cap / kw) and capD / kdw; both
        // fall as kw and kdw grow and rounding keeps that order, so it is the step of its largest
        // kw and largest kdw: one square root and two divisions a particle, not a spring.
        std::vector<double> kwMax(n, 0.0), kdwMax(n, 0.0);
        auto add = [&](const std::vector<Spring>& springs, double ks, double kds) {
            for (const Spring& s : springs) {
                const double w = double(cloth.invMass[s.a]) + double(cloth.invMass[s.b]);
                const double kw = ks * s.weight * w, kdw = kds * s.weight * w;
                for (Index p : {s.a, s.b}) {
                    kwMax[p] = std::max(kwMax[p], kw);
                    kdwMax[p] = std::max(kdwMax[p], kdw);
                }
            }
        };
        const AskedStiffness asked = structuralAsked(settings);
        add(cloth.springs, asked.stiffness, dampingFree ? 0.0 : asked.damping);
        if (m.model == MaterialModel::Linear) add(cloth.bends, m.bendStiffness, dampingFree ? 0.0 : m.bendDamping);
        for (Index p = 0; p < n; ++p) {
            if (kwMax[p] > 0) springStep[p] = std::sqrt(double(kStiffnessCap) / kwMax[p]);
            if (alsoDampingFree) springStepFree[p] = springStep[p];
            if (kdwMax[p] > 0) springStep[p] = std::min(springStep[p], double(kDampingCap) / kdwMax[p]);
        }
    }
    // The guard's budget and the air drag's share of it (guardParticleBudget counts it too).
    const bool budgeted = bound == StepBound::Budget;
    const double budget = budgeted ? double(kParticleBudget) : 1.0;
    const double drag = budgeted ? double(airDragPerMass(settings, cloth.density)) : 0.0;
    // (A / 2) dt^2 + B dt = budget
    auto stepOf = [&](double A, double B, double step) {
        if (A > 0) return std::min(step, (std::sqrt(B * B + 2 * A * budget) - B) / A);
        if (B > 0) return std::min(step, budget / B);
        return step;
    };
    ParticleSteps out;
    out.steps.reserve(n);
    if (alsoDampingFree) out.freeSteps.reserve(n);
    for (Index p = 0; p < n; ++p) {
        const double w = cloth.invMass[p];
        if (w == 0.0)
            continue;
        const double A = k[p] * w, B = kd[p] * w + drag;
        out.steps.emplace_back(stepOf(A, B, springStep[p]), 1.0 / w);
        if (alsoDampingFree) out.freeSteps.emplace_back(stepOf(A, drag, springStepFree[p]), 1.0 / w);
    }
    return out;
}

// The step every particle meets but the ones that need a shorter one and together hold at most
// lightMassFraction of the mass: walk up the shortest steps until their mass passes it. (The total
// is summed in particle order; a full sort summed it in step order, which differs in the last bits,
// so the answer could differ only where the share's edge falls within that rounding.)
double stepBeyondTheLightest(StepList& steps, double lightMassFraction) {
    if (steps.empty())
        return std::numeric_limits<double>::infinity();
    double freeMass = 0;
    for (const auto& sm : steps)
        freeMass += sm.second;
    const double light = lightMassFraction * freeMass;
    // Only the shortest few need an order (a full sort of every particle's step was most of this
    // estimate, paid once per tearing frame): a prefix twice the light share by count, grown while
    // its mass does not pass the share. Sorted, the prefix is the sorted array's start.
    size_t prefix = std::min(steps.size(), size_t(2.0 * lightMassFraction * double(steps.size())) + 64);
    for (;;) {
        std::nth_element(steps.begin(), steps.begin() + std::ptrdiff_t(prefix - 1), steps.end());
        std::sort(steps.begin(), steps.begin() + std::ptrdiff_t(prefix));
        double below = 0;
        for (size_t i = 0; i < prefix; ++i) {
            below += steps[i].second;
            if (below > light)
                return steps[i].first;
        }
        if (prefix == steps.size())
            return steps.back().first;
        prefix = std::min(steps.size(), 2 * prefix);
    }
}

} // namespace

double stableStepEstimate(const Cloth& cloth, const Settings& settings) {
    if (!isExplicit(settings.time.integrator))
        return std::numeric_limits<double>::infinity();
    double best = std::numeric_limits<double>::infinity();
    for (const auto& [step, mass] : stepsAndMasses(cloth, settings, StepBound::Stable, implicitDampingAlways(settings)).steps)
        best = std::min(best, step);
    return best;
}

double guardStepEstimate(const Cloth& cloth, const Settings& settings, double lightMassFraction, bool interacting,
                         bool dampingFree) {
    if (!isExplicit(settings.time.integrator))
        return std::numeric_limits<double>::infinity();
    const bool caps = interacting || settings.material.model == MaterialModel::Kes;
    ParticleSteps p = stepsAndMasses(cloth, settings, caps ? StepBound::SpringCaps : StepBound::Budget, dampingFree);
    return stepBeyondTheLightest(p.steps, lightMassFraction);
}

GuardSteps guardStepEstimates(const Cloth& cloth, const Settings& settings, double lightMassFraction, bool interacting) {
    if (!isExplicit(settings.time.integrator))
        return {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    const bool caps = interacting || settings.material.model == MaterialModel::Kes;
    ParticleSteps p = stepsAndMasses(cloth, settings, caps ? StepBound::SpringCaps : StepBound::Budget, false, true);
    return {stepBeyondTheLightest(p.steps, lightMassFraction), stepBeyondTheLightest(p.freeSteps, lightMassFraction)};
}

} // namespace clothtear
