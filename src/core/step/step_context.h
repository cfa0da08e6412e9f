// The step context: everything a sub-step's phases read that follows from the settings and the
// world at the start of the sub-step, derived once (makeStepContext) so a rule lives in one place:
// the sub-step length, gravity, which phases run, the tear thresholds, the air terms, the threads.
// Phases are functions of (StepContext, Cloth, StepState) (phases.h), as Box2D v3's stages take a
// b2StepContext.
#pragma once
#include "clothtear/world.h"
#include "revisions.h"

#include <algorithm>
#include <vector>

namespace clothtear {

struct StepState;

struct StepContext {
    const Settings* settings = nullptr;
    float dt = 0;    // s, this sub-step
    float invDt = 0; // 1/s
    double time = 0; // s, simulated time at the start of the sub-step
    Vec3 gravity = Vec3::Zero(); // m/s^2
    Integrator integrator = Integrator::SemiImplicitEuler;
    bool reference = false; // implicit Euler or XPBD: springs inside the integrator, no guard
    int threads = 1;        // threads for this cloth (threadsFor)

    // Which phases run. A phase the scene does not need is not entered.
    bool windBlows = false; // wind on, with a speed and a drag coefficient
    bool collide = false;   // balls present
    bool contact = false;   // balls or the ground
    bool limiting = false;  // limit.enabled with iterations > 0
    bool scan = false;      // the limit phase runs: limiting, or the strain scan for tearing
    bool tearing = false;   // tear.enabled
    bool checkFinite = false; // check.finite or a Debug build: NaN/Inf located at every phase boundary

    // Length limit and tearing, as length ratios (1 + strain).
    float maxRatio = 1;   // 1 + limit.max_stretch
    float heldRatio = 1;  // under a ball: up to the tear threshold (the ball decides, Onal 4.1)...
    float tearGauge = 0;  // m: ...for springs at least this long; a shorter one holds the same stretch
                          // past the limit in metres (heldLength)
    float tearRatio = 1e30f; // 1 + tear.threshold (1e30 without tearing)
    float weakRatio = 1e30f; // springs touching a weak point or a one-point connection (tearStrainFor)
    float hemRatio = 1e30f;  // springs touching a hem (tearStrainFor)
    bool velocityFix = true; // inelastic limit fix; off for Verlet, whose moves are velocities

    // Air, as the explicit integrators apply it.
    // The stability guard caps springs one by one (spring_caps.h): with the kes law, and with the
    // linear material while a ball is near or a hand moves (StepState::interacting).
    bool perSpringCaps = false;
    // The springs' damping taken implicitly this frame (time.damping implicit, or auto where the
    // guard chose it: StepState::dampingImplicit): the springs phase computes the elastic forces
    // only and the integrator takes the damping (integrate.cpp).
    bool implicitDamping = false;
    float dragPerMass = 0; // 1/s, a = -dragPerMass v, capped by the guard (guardDragPerMass)
    float keep = 1;        // Keserica model: velocity kept per sub-step

    // The world's parts the phases act on besides the cloth.
    std::vector<Ball>* balls = nullptr;
    std::vector<Driver>* drivers = nullptr;
    StepProfile* profile = nullptr;
    TearLog* tearLog = nullptr;
    bool ballBroadPhase = true;
    Revisions revisions; // of the caches' inputs, this sub-step
};

// How long a spring under a ball may get (the limit holds it there, and it tears there):
// rest x (1 + limit.max_stretch), plus the stretch past the limit that a strip of fabric
// tear.gauge_length long holds at the tear threshold, (threshold - max_stretch) x gauge, or x rest
// for a spring longer than the gauge. What a ball stretches past the limit gathers in the ring of
// springs between the held fabric and the contact, and that ring is one mesh spacing wide: a strain
// threshold on it alone was a threshold on metres / spacing, so the thesis' big slow ball
// (ball-r2-v3, Onal 4.1: the cloth slides over it) tore at 96 and 144 a side and not at 48
// (bench/README.md, "A ball tears by metres of stretch").
struct HeldLength {
    float limitRatio = 1;  // (1 + limit.max_stretch) x scale
    float excessRatio = 0; // (heldRatio - limitRatio) x scale
    float gauge = 0;       // m
    float operator()(float rest) const { return limitRatio * rest + excessRatio * std::max(rest, gauge); }
    // The smallest held ratio: a spring at least the gauge long.
    float minRatio() const { return limitRatio + excessRatio; }
};
inline HeldLength heldLength(const StepContext& c, float scale) {
    return HeldLength{c.maxRatio * scale, (c.heldRatio - c.maxRatio) * scale, c.tearGauge};
}

// time.damping may take the damping implicitly: semi-implicit Euler with the linear material (the
// other explicit integrators and the kes law keep their explicit damping; the references have their
// own), and the setting not explicit.
inline bool implicitDampingAllowed(const Settings& s) {
    return s.time.damping != DampingMode::Explicit && s.time.integrator == Integrator::SemiImplicitEuler &&
           s.material.model == MaterialModel::Linear;
}
// ...and taken implicitly in every frame (time.damping = implicit), not only where auto chooses it.
inline bool implicitDampingAlways(const Settings& s) {
    return implicitDampingAllowed(s) && s.time.damping == DampingMode::Implicit;
}
// ...and taken implicitly now: always, or where the guard chose it under auto (guardChose:
// StepState::dampingImplicit, World::guardSubsteps; checked against the settings again, which a
// user may change between a frame's start and a sub-step run on its own).
inline bool implicitDampingNow(const Settings& s, bool guardChose) {
    return implicitDampingAlways(s) || (implicitDampingAllowed(s) && guardChose);
}

// Wind acts: on, with a speed and a drag coefficient (the wind phase runs; a cloth in wind never sleeps).
bool windBlows(const Settings& settings);

// Threads worth using for a cloth of n particles (forking costs a few microseconds).
int threadsFor(size_t particles);

// Air drag per unit mass, 1/s (a = -airDragPerMass v): air.drag_coefficient / density with the
// physical model, 0 with Keserica's (a factor on v instead).
float airDragPerMass(const Settings& settings, float density);

// Air drag of the explicit integrators: with the guard on, capped at 0.5 / dt (explicit drag
// v -= c/rho v dt overshoots past zero velocity beyond 1 / dt and explodes beyond 2 / dt; a light
// cloth in the safe ranges reaches c/rho = 500 1/s).
float guardDragPerMass(const Settings& settings, float density, float dt);

// Builds the context of a sub-step of length dt (observing the revisions of the caches' inputs).
StepContext makeStepContext(World& world, StepState& state, float dt);

} // namespace clothtear
