// makeStepContext: the settings turned into what the phases of one sub-step read (step_context.h).
#include "step_context.h"

#include "parallel.h"
#include "sleep.h"
#include "step_state.h"

#include <algorithm>

namespace clothtear {

int threadsFor(size_t particles) { return particles >= 2048 ? std::min(maxThreads(), kMaxThreadSlots) : 1; }

bool windBlows(const Settings& s) { return s.wind.enabled && s.wind.speed > 0.f && s.wind.dragCoefficient > 0.f; }

float airDragPerMass(const Settings& settings, float density) {
    return settings.air.model == AirModel::Drag ? settings.air.dragCoefficient / density : 0.f;
}

float guardDragPerMass(const Settings& settings, float density, float dt) {
    const float c = airDragPerMass(settings, density);
    return settings.time.stabilityGuard ? std::min(c, 0.5f / dt) : c;
}

// Debug builds check for NaN/Inf at every phase boundary whatever check.finite says.
#if CLOTHTEAR_CHECK_FINITE
constexpr bool kAlwaysCheckFinite = true;
#else
constexpr bool kAlwaysCheckFinite = false;
#endif

StepContext makeStepContext(World& w, StepState& state, float dt) {
    const Settings& S = w.settings;
    StepContext c;
    c.settings = &w.settings;
    c.dt = dt;
    c.invDt = 1.f / dt;
    c.time = w.time;
    c.gravity = Vec3(S.gravity.x, S.gravity.y, S.gravity.z);
    c.integrator = S.time.integrator;
    c.reference = !isExplicit(S.time.integrator);
    c.threads = threadsFor(w.cloth.particleCount());

    c.windBlows = windBlows(S);
    const bool ballsAwake = anyBallAwake(w.balls);
    c.collide = ballsAwake;
    c.contact = ballsAwake || S.collision.ground;
    c.limiting = S.limit.enabled && S.limit.iterations > 0;
    c.tearing = S.tear.enabled;
    c.scan = c.limiting || c.tearing; // the limit pass doubles as the strain scan
    c.checkFinite = kAlwaysCheckFinite || S.check.finite;

    c.maxRatio = 1.f + S.limit.maxStretch;
    c.tearRatio = c.tearing ? 1.f + tearStrainFor(S.tear, false) : 1e30f;
    c.weakRatio = c.tearing ? 1.f + tearStrainFor(S.tear, true) : 1e30f;
    c.hemRatio = c.tearing ? 1.f + tearStrainFor(S.tear, false, true) : 1e30f;
    c.heldRatio = std::max(c.maxRatio, 1.f + S.tear.threshold);
    c.tearGauge = c.tearing ? S.tear.gaugeLength : 0.f; // without tearing a ball stretches to the threshold only
    c.velocityFix = S.time.integrator != Integrator::Verlet;

    c.dragPerMass = guardDragPerMass(S, w.cloth.density, dt);
    c.perSpringCaps = S.time.stabilityGuard && (S.material.model == MaterialModel::Kes || state.interacting);
    c.implicitDamping = implicitDampingNow(S, state.dampingImplicit);
    c.keep = S.air.model == AirModel::Keserica ? 1.f - S.air.kesericaFactor : 1.f;

    c.balls = &w.balls;
    c.drivers = &w.drivers;
    c.profile = &w.profile;
    c.tearLog = &w.tearLog;
    c.ballBroadPhase = S.collision.broadPhase;
    c.revisions = state.revisions.observe(w, dt);
    return c;
}

} // namespace clothtear
