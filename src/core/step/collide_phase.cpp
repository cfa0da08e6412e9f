// The two ball phases of the step: collide (before the limit: balls move and push the cloth) and
// contact (after it: balls give way where the limit held the cloth; the ground). Kernels: collide.h.
#include "collide.h"
#include "phases.h"

#include <algorithm>
#include <limits>

namespace clothtear {
namespace {

// The ball broad phase needs a bound on every triangle edge (collide.cpp, trianglesIn). With tearing,
// a spring past its tear threshold tears in this sub-step's tear phase; with the limit alone, none
// stays past the limit; the factor 2 covers what one sub-step of motion adds before the limit and
// the tear phase run. Without either, no bound: every triangle is tested.
float ballEdgeBound(const StepContext& ctx, const StepState& state) {
    const Settings& S = *ctx.settings;
    const TearSettings& T = S.tear;
    const float maxRest = state.springs.maxRest;
    float strain = std::numeric_limits<float>::infinity();
    if (ctx.tearing) strain = std::max({T.threshold, T.weakThreshold, T.onePointThreshold});
    else if (ctx.limiting) strain = S.limit.maxStretch;
    if (!ctx.ballBroadPhase || maxRest <= 0.f) strain = std::numeric_limits<float>::infinity();
    return 2.f * maxRest * (1.f + strain);
}

} // namespace

void phaseCollide(const StepContext& ctx, Cloth& cloth, StepState& state) {
    collideBalls(cloth, *ctx.balls, ctx.settings->collision, ctx.gravity, ctx.dt, ballEdgeBound(ctx, state),
                 state.packed.data(), state.contacts);
}

void phaseContact(const StepContext& ctx, Cloth& cloth, StepState& state) {
    // Without limiting nothing holds the cloth back against a ball: the collide phase said it all.
    settleContacts(cloth, *ctx.balls, ctx.settings->collision, ctx.dt, ballEdgeBound(ctx, state), ctx.limiting,
                   state.contacts, state.contactOf);
    state.contacts.clear();
}

} // namespace clothtear
