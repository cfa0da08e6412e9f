// The step: a frame of sub-steps, each a list of named, timed phases over one step context
// (phases.h), then the frame's bookkeeping. See docs/architecture.md for what each phase reads and
// writes.
#include "clothtear/world.h"

#include "finite_check.h"
#include "float_env.h"
#include "parallel.h"
#include "phase_timer.h"
#include "phases.h"
#include "sleep.h"

#include <cmath>
#include <limits>

namespace clothtear {

const char* phaseName(Phase p) {
    static const char* names[] = {"forces",  "springs", "wind", "integrate",  "collide",
                                  "limit", "contact", "tear", "bookkeeping"};
    return names[int(p)];
}

namespace {

// Can a ball touch the cloth this frame? Its centre is within its radius, a mean rest length and
// the distance it and the cloth's fastest particle close in a frame of the cloth's bounding box.
bool ballNearCloth(const World& w) {
    if (w.balls.empty() || w.cloth.particleCount() == 0) return false;
    Vec3 lo = w.cloth.x[0], hi = lo;
    float fastest2 = 0.f;
    for (size_t p = 0; p < w.cloth.particleCount(); ++p) {
        lo = lo.cwiseMin(w.cloth.x[p]);
        hi = hi.cwiseMax(w.cloth.x[p]);
        fastest2 = std::max(fastest2, w.cloth.v[p].squaredNorm());
    }
    const float frame = w.settings.time.frameDt, spacing = float(meanRestLength(w.cloth));
    for (const Ball& b : w.balls) {
        if (b.asleep) continue; // nothing within its reach moves (ball_sleep.cpp)
        const float reach = b.radius + spacing + (b.v.norm() + std::sqrt(fastest2)) * frame;
        const Vec3 nearest = b.x.cwiseMax(lo).cwiseMin(hi);
        if (!((b.x - nearest).norm() > reach)) return true; // a non-finite ball counts as near
    }
    return false;
}

// After phase `after` (-1: before the sub-step's first phase, i.e. set from outside the step): the
// first non-finite value, with the phase, frame and time, into nonFiniteWhere. The force buffers are
// read after the phases that fill them (springs, wind); the integrator clears them.
void checkFinite(World& w, const StepState& state, int after) {
    if (!w.finite) return; // the first one is the one to trace
    const bool forces = after == int(Phase::Springs) || after == int(Phase::Wind);
    const std::string what = findNonFinite(w.cloth, w.balls, forces ? &state.threads : nullptr);
    if (what.empty()) return;
    w.finite = false;
    const std::string where = after < 0 ? std::string("before a sub-step (set from outside the step)")
                                        : std::string("after phase '") + phaseName(Phase(after)) + "'";
    w.nonFiniteWhere = where + " at frame " + std::to_string(w.steps) + ", t = " + std::to_string(w.time) + " s: " + what;
}

// Once per frame: the largest structural strain (compared as squared length ratios, one square
// root at the end) and the first non-finite particle, both split over the threads.
void phaseBookkeeping(World& w) {
    PhaseTimer timer(w.profile, Phase::Bookkeeping);
    const Cloth& cloth = w.cloth;
    const size_t ns = cloth.springs.size(), n = cloth.particleCount();
    const int threads = threadsFor(n);
    float worstLen2[kMaxThreadSlots], worstRest2[kMaxThreadSlots];
    size_t firstBad[kMaxThreadSlots];
    float speed2[kMaxThreadSlots];
    const bool checkFinite = w.finite;
    parallelRegion(std::max(ns, n), threads, [&](int t, int nt) {
        const Chunk c = chunkOf(ns, t, nt);
        float len2Max = 0.f, rest2Max = 1.f; // ratio len2Max / rest2Max, kept without dividing
        for (size_t i = c.begin; i < c.end; ++i) {
            const Spring& s = cloth.springs[i];
            const float len2 = (cloth.x[s.b] - cloth.x[s.a]).squaredNorm(), rest2 = s.rest * s.rest;
            if (len2 * rest2Max > len2Max * rest2) len2Max = len2, rest2Max = rest2;
        }
        worstLen2[t] = len2Max;
        worstRest2[t] = rest2Max;
        firstBad[t] = n;
        speed2[t] = 0.f;
        if (!checkFinite) return;
        const Chunk pc = chunkOf(n, t, nt);
        float fastest = 0.f; // for sleep.cpp
        for (size_t p = pc.begin; p < pc.end; ++p) {
            if (!cloth.x[p].allFinite() || !cloth.v[p].allFinite()) {
                firstBad[t] = p;
                break;
            }
            fastest = std::max(fastest, cloth.v[p].squaredNorm());
        }
        speed2[t] = fastest;
    });
    const int used = (threads > 1 && std::max(ns, n) >= kParallelWork) ? threads : 1;
    float worst = 0.f, fastest2 = 0.f;
    size_t bad = n;
    for (int k = 0; k < used; ++k) {
        worst = std::max(worst, std::sqrt(worstLen2[k] / worstRest2[k]) - 1.f);
        bad = std::min(bad, firstBad[k]);
        fastest2 = std::max(fastest2, speed2[k]);
    }
    w.maxStrain = worst;
    w.maxSpeed = checkFinite ? std::sqrt(fastest2) : std::numeric_limits<float>::infinity();
    if (w.finite) {
        if (bad < n) {
            w.finite = false;
            w.nonFiniteWhere = "particle " + std::to_string(bad) + " at frame " + std::to_string(w.steps);
        }
        for (const Ball& b : w.balls)
            if (!b.x.allFinite() || !b.v.allFinite()) w.finite = false;
    }
}

} // namespace

void World::step() {
    const FlushSubnormals flush; // float_env.h
    applySettings();
    StepState& state = *state_;
    if (stayAsleep(*this, state)) {
        moveBallsBesideASleepingCloth(*this, state); // none of them can reach it this frame
        time += settings.time.frameDt;
        ++steps;
        ++sleptFrames;
        return;
    }
    wakePiecesIfTouched(*this, state);
    wakeBallsIfTouched(*this, state); // after the pieces: a piece woken under a ball wakes it
    if (settings.sleep.enabled) state.sleep.frameStart = cloth.x;
    // A ball near the cloth or a hand moving it: the guard's conservative step, springs capped one
    // by one (stability.cpp). Their tears are made in one sub-step (bench/README.md, "Ball outcomes
    // against the sub-step") and were measured and are tested at that step.
    state.interacting = ballNearCloth(*this) || driversMove(drivers);
    frameSubsteps = guardSubsteps();
    profile.dampingImplicit = implicitDampingNow(settings, state.dampingImplicit);
    if (profile.dampingImplicit) profile.dampingImplicitSubsteps += uint64_t(frameSubsteps);
    state.substepsNow = frameSubsteps;
    for (int i = 0; i < frameSubsteps; ++i) substep();
    state.substepsNow = 0;
    const bool springsExplicit = isExplicit(settings.time.integrator);
    guardCappedSprings = springsExplicit ? state.springs.cappedSprings : 0;
    guardStiffnessKept = springsExplicit ? state.springs.stiffnessKept : 1.f;
    guardDampingKept = springsExplicit ? state.springs.dampingKept : 1.f;
    phaseBookkeeping(*this);
    ++steps;
    updatePieceSleep(*this, state); // first: the World's sleep then records the masses it leaves
    updateBallSleep(*this, state);  // after the pieces: a ball sleeps once what it rests on does
    updateSleep(*this, state);
}

// The stability guard, first part: with an explicit integrator, take enough sub-steps that the
// material as set is stable (stability.cpp), up to time.max_substeps. Whatever is still too stiff
// at that step is scaled in the spring cache (springs.cpp: per particle into the Gershgorin budget,
// and spring by spring while a ball is near or a hand moves), so the guard never lets a frame
// explode, and where the budget allows, the cloth keeps its stiffness.
// The step is chosen for all but the lightest kGuardLightMass of the cloth's mass: tearing halves
// triangles, and a torn cloth's small midpoint particles would otherwise multiply the sub-steps
// of the whole cloth (a 2 m cloth at 65 x 65 went from 20 to 200 per frame after 11 tears); their
// springs are capped instead, and the limit holds their length.
//
// The springs' damping (time.damping): taken explicitly it bounds the step by m / sum(kd), which
// shrinks as the spacing squared; taken implicitly only the stiffness does, at a second spring pass
// and integrator stage a sub-step (kImplicitDampingCost). With auto the guard takes it implicitly
// where the explicit damping's step would be past time.max_substeps (so the guard would soften the
// cloth) and the stiffness's step is not, and where the implicit sub-steps cost less than the
// explicit ones; both keep the material as set (bench/README.md, "The springs' damping and the
// guard's step").
int World::guardSubsteps() {
    const TimeSettings& T = settings.time;
    StepState& state = *state_;
    state.dampingImplicit = false;
    if (!T.stabilityGuard || !isExplicit(T.integrator) || T.maxSubsteps <= T.substeps) return T.substeps;
    const Revisions& now = state.revisions.observe(*this); // the estimate does not depend on dt
    GuardCache& G = state.guard;
    if (!G.stamp.fresh(now, GuardCache::kDeps)) {
        G.resting = G.interacting = {};
        G.stamp.set(now);
    }
    // Each estimate only when a frame needs it: while a hand tears the cloth every tear changes the
    // topology, and the budget's step, unused then, was half the guard's cost. Auto wants both of
    // one kind, from one walk over the springs (guardStepEstimates).
    const bool caps = state.interacting;
    GuardCache::Estimate& E = caps ? G.interacting : G.resting;
    const bool autoDamping = implicitDampingAllowed(settings) && T.damping == DampingMode::Auto;
    auto frameSteps = [&](double step) { return std::ceil(double(T.frameDt) / step); };
    auto within = [&](double need) { return need > double(T.maxSubsteps) ? T.maxSubsteps : std::max(T.substeps, int(need)); };
    if (!autoDamping) {
        const bool free = implicitDampingAlways(settings);
        bool& known = free ? E.freeKnown : E.known;
        double& value = free ? E.freeStep : E.step;
        if (!known) {
            value = guardStepEstimate(cloth, settings, kGuardLightMass, caps, free);
            known = true;
        }
        return within(frameSteps(value));
    }
    if (!E.known || !E.freeKnown) {
        const GuardSteps both = guardStepEstimates(cloth, settings, kGuardLightMass, caps);
        E.step = both.withDamping;
        E.freeStep = both.dampingFree;
        E.known = E.freeKnown = true;
    }
    const double need = frameSteps(E.step), free = frameSteps(E.freeStep);
    const double max = double(T.maxSubsteps), floor = double(T.substeps);
    const bool softens = need > max;
    const bool cheaper = kImplicitDampingCost * std::max(floor, free) < std::max(floor, need);
    if (free <= max && (softens || cheaper)) {
        state.dampingImplicit = true;
        return within(free);
    }
    return within(need);
}

void World::substep() {
    const FlushSubnormals flush; // float_env.h (step() set it already; substep() is public too)
    StepState& state = *state_;
    const int substeps = state.substepsNow > 0 ? state.substepsNow : settings.time.substeps;
    const StepContext ctx = makeStepContext(*this, state, settings.time.frameDt / float(substeps));
    // Debug builds and check.finite: the first phase boundary with a NaN/Inf is reported
    // (nonFiniteWhere). A check after a phase that did not run finds what the previous one found.
    auto check = [&](int afterPhase) {
        if (ctx.checkFinite) checkFinite(*this, state, afterPhase);
    };
    // Runs phase p when `on`, timed; then the finite check at its boundary (forces has none: it
    // only sizes buffers).
    auto phase = [&](Phase p, bool on, auto&& body) {
        if (on) {
            PhaseTimer t(profile, p);
            body();
        }
        if (p != Phase::Forces) check(int(p));
    };
    check(-1);
    phase(Phase::Forces, true, [&] { phaseForces(ctx, cloth, state); });
    phase(Phase::Springs, !ctx.reference, [&] { phaseSprings(ctx, cloth, state); });
    phase(Phase::Wind, ctx.windBlows, [&] { phaseWind(ctx, cloth, state); });
    phase(Phase::Integrate, true, [&] {
        if (ctx.reference) phaseIntegrateReference(ctx, cloth, state);
        else phaseIntegrate(ctx, cloth, state);
    });
    phase(Phase::Collide, ctx.collide, [&] { phaseCollide(ctx, cloth, state); });
    phase(Phase::Limit, ctx.scan, [&] { phaseLimit(ctx, cloth, state); });
    phase(Phase::Contact, ctx.contact, [&] { phaseContact(ctx, cloth, state); });
    phase(Phase::Tear, ctx.tearing && !state.tearCandidates.empty(), [&] { phaseTear(ctx, cloth, state); });
    time += ctx.dt;
    profile.substeps++;
}

} // namespace clothtear
