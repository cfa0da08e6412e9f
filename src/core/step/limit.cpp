// The limit phase: strain scan, tethers and Provot length limiting (Gauss-Seidel or averaged Jacobi).
//
// Provot length limiting (Onal 2.1.1): a spring longer than rest * (1 + maxStretch) pulls its ends
// together, split by inverse mass; pinned ends never move; every correction is an equal and
// opposite pair, so momentum is conserved. limit.solver: Gauss-Seidel (default) applies each
// spring's over-relaxed correction at once, so the next spring sees it: a pull travels along the
// list within one pass, and a cloth hanging on the limit converges in passes of the order of its
// depth (issue 12: averaged Jacobi at 12 passes left a 2 m cloth pinned on its side at strain
// 0.12-0.16). Jacobi divides each spring's correction by the larger number of corrections its ends
// get and applies them after the pass (its result does not depend on spring order).
// A spring that tears this sub-step is left alone (Onal 3.2): the scan records every spring at
// or above its tear threshold (the tear phase's candidates) and the passes skip them. If there are
// more than tear.max_per_step candidates, only the most strained max_per_step are exempt; the
// passes limit the others, so a spring is never left unlimited without being torn (that ran away).
// A tear starts only from a load the limit could not hold (issue 12): a spring that this sub-step's
// motion alone carried from within the limit past its threshold (its ends' start-of-step positions,
// x - v dt, within the limit) is limited, not torn, unless a ball touches it, it touches a tear's tip
// or hinge, or a hand (driver) moves: the exceptions where the limit is not a hard cap. Such a jump
// is the step's overshoot: the limit, a hard cap, stops the spring at the limit as dt goes to 0.
// Measured: a 6 m cloth pinned on its side whips through its fold at 19 m/s between neighbours,
// and one 1.3 ms sub-step took a spring from 0.084 to 0.39 (bench/README.md, "Overshoot is not a load").
//
// Order and cost, all in one parallel region (LimitSolve::run):
//   1. scan     reads every structural spring once (four at a time, kernels.h); most leave after one
//               squared-length compare, no square root. Lists the candidates and the springs over
//               the limit.
//   2. tethers  (tethers.h) pull every particle back within reach of its anchor; skipped when the
//               scan saw no spring past the tethers' reach ratio (then none can pull). A tether whose
//               path runs through a tear candidate (or a ball contact) does not pull this sub-step;
//               the scan comes first so that a spring reaching its threshold is seen before anything
//               pulls it back. The springs of the particles a tether moved are listed if it pushed
//               them over the limit (a pull sideways, towards another anchor, can).
//   3. passes   over the listed springs only (limit.solver): Gauss-Seidel, in place, in one order
//               (the threads' lists merged in thread order), forwards and backwards in turn: on one
//               thread, or on several by regions of the cloth that share no particle
//               (regionPasses); or averaged Jacobi over the threads. A pass drops the
//               springs back within the limit (to kLimitTolerance) and lists the springs of the
//               particles it moved that it pushed over (particle-spring table), so a pass covers
//               what a full pass would correct; they stop when a pass corrects nothing (passCap:
//               at most). At rest that is a few hundred springs, not all of them, per sub-step.
#include "env_switch.h"
#include "kernels.h"
#include "limit_ball.h"
#include "limit_expand.h"
#include "limit_kernels.h"
#include "parallel.h"
#include "phases.h"
#include "tethers.h"
#include "tear_topology.h"

#include <algorithm>
#include <atomic>
#include <cassert>
#include <cmath>
#include <functional>
#include <limits>
#include <string>

namespace clothtear {

// Does a driver move particles (the drag tool, the pull and tension scenes)?
bool driversMove(const std::vector<Driver>& drivers) {
    for (const Driver& d : drivers)
        if (!d.particles.empty() && d.velocity.squaredNorm() > 0.f) return true;
    return false;
}

namespace {

bool limitSkipsAllowed() { return envSwitchOn("CLOTHTEAR_LIMIT_SKIPS"); }
// Gauss-Seidel by regions on several threads (regionPasses); CLOTHTEAR_LIMIT_REGIONS=0: on thread 0
// alone, in the one-thread order, for the benchmarks and tests that compare the two.
bool limitRegionsAllowed() { return envSwitchOn("CLOTHTEAR_LIMIT_REGIONS"); }

// Sub-steps the expand prefilter rests after it found springs over the limit (prefilterPays).
constexpr uint32_t kPrefilterWait = 4;

// Lists shorter than this are worked by one thread (a barrier costs more than the work).
constexpr size_t kSerialList = 2048;
// Gauss-Seidel on several threads (regionPasses): lists shorter than this are one region, thread
// 0's (the two barriers a split pass adds cost more than half of such a pass).
constexpr size_t kRegionMinList = 128;

// Is a spring of rest length `rest` and squared length len2 over its limit by more than the
// tolerance, given its ends' flags (or-ed)? Springs under a ball may stretch up to their held length
// (heldLength: the tear threshold, or a gauge's stretch): the ball, not the limit, decides where they are.
inline bool exceedsLimit(uint8_t endFlags, float rest, float len2, float doneRatio, const HeldLength& heldDone) {
    return len2 > sq((endFlags & kTouched) ? heldDone(rest) : rest * doneRatio);
}

// Rebuilds the limit cache when the topology, the pinned particles or the drivers changed. Tether
// anchors are the pinned particles that no driver moves: a tether to a moving clamp would drag the
// cloth along with it and put all the stretch at the border between the clamp's particles and the
// others.
void refreshLimitCache(const StepContext& ctx, const Cloth& cloth, LimitCache& C) {
    if (C.stamp.fresh(ctx.revisions, LimitCache::kDeps)) return;
    std::vector<uint8_t> anchor(cloth.particleCount(), 0);
    for (Index p = 0; p < cloth.particleCount(); ++p) anchor[p] = cloth.invMass[p] == 0.f;
    for (const Driver& d : *ctx.drivers)
        for (Index p : d.particles)
            if (p < anchor.size()) anchor[p] = 0;
    buildLimitCache(cloth, anchor, C);
    C.stamp.set(ctx.revisions);
}


// Gauss-Seidel: a pass carries a correction along the whole list in the list's direction, but
// only one spring against it, so a pull from the anchors across a cloth D springs deep can take
// on the order of D passes; the passes may run to kPassesPerDepth x D (limit.iterations at least)
// and stop as soon as nothing is over the limit. Measured (bench/README.md, "Does the cloth
// hold?"): a 2 m cloth pinned on its left edge needs about 100 passes at 33 x 33 and 200 at 65 x 65
// while it swings. Without anchors, D is the side of a square of the cloth's particles. Jacobi:
// limit.iterations, as set.
// While a driver moves particles, not to convergence: the hand's pull is what may stretch springs
// past the limit (issue 12, goal 5), and chasing it to convergence every sub-step, with the cloth
// taut between the hand and the pins, ran the passes to the cap in most sub-steps: a curtain dragged
// sideways in the app (assets/screenshots/tear.txt) took 1.9 s per frame at 128 x 128 (70 % of the
// sub-steps at 512 passes) and 178 ms at 80 x 80 (bench/README.md, "Dragging").
// Instead kHandPassesPerDepth x D passes, a fixed share of the depth, not a fixed count: each pass
// carries the hand's pull about one spring further (expand lists a corrected spring's neighbours for
// the next pass), so a fixed count spread the hand's excess over a fixed number of springs, fewer
// metres at a finer mesh, and the sideways pull tore 1 s later at 40 a side than at 80 and 160, at a
// different angle (bench/README.md, "The hand's passes by depth"). An eighth of the depth is the 12
// passes of before at about 100 a side (the drag's resolutions 80 and 128 were measured with those).
// While a ball touches the cloth (this sub-step's contacts), D passes: one crossing of the cloth from
// the pins. A ball that drags the curtain taut against its pins (the ball tool's 2 kg at 8 m/s) ran
// the passes towards 4 x D over lists spanning the whole cloth in most sub-steps of the hit: the
// throw took 1.2 s a frame at 128 x 128 and ran at 10 FPS at 80 x 80. The ball is the deliberate
// exception of issue 12 goal 5 there, like the hand. A quarter of D or less tore `ball-r2-v3` (must
// hold) at the thesis's 48 a side with tear.threshold 10 % lower; D holds all five outcomes of the
// test's sweep on one and two threads (bench/README.md, "A ball at 128 a side").
constexpr int kPassesPerDepth = 4;
constexpr double kHandPassesPerDepth = 0.125;
constexpr int kBallPassesPerDepth = 1;
int passCap(const StepContext& ctx, const Cloth& cloth, const LimitCache& C, bool ballTouches) {
    const LimitSettings& L = ctx.settings->limit;
    if (L.solver != LimitSolver::GaussSeidel || L.iterations <= 0) return L.iterations;
    const uint32_t depth = C.depth > 0 ? C.depth : uint32_t(std::sqrt(double(cloth.particleCount())));
    if (driversMove(*ctx.drivers)) return std::max(1, int(std::lround(kHandPassesPerDepth * double(depth))));
    if (ballTouches) return std::max(L.iterations, kBallPassesPerDepth * int(depth));
    return std::max(L.iterations, kPassesPerDepth * int(depth));
}

// One sub-step's limit phase: what the parts share, and the parts as named functions. run() calls
// them from every thread of one parallel region, with barriers between them.
class LimitSolve {
public:
    LimitSolve(const StepContext& ctx, Cloth& cloth, StepState& state);
    void run();
    int cappedSprings = 0; // springs the last allowed pass still corrected (thread 0 writes it)
    int passesRun = 0;     // passes that looked at a non-empty list (thread 0 writes it)
    int regionPassesRun = 0; // of them split by region over the threads (regionPasses; thread 0)
    bool tethersSkipped = false, expandSkipped = false; // (thread 0 writes them)
    bool prefilterFailed = false; // the prefilter ran and found springs over: expand ran anyway
    int listingsAvx2 = 0;         // expand calls the AVX2 kernel ran on moved particles (alone: one writer)

private:
    // Is an end of spring s under a ball this sub-step?
    bool underBall(const Spring& s) const { return ((flags_[s.a] | flags_[s.b]) & kTouched) != 0; }
    // Is spring s (squared length len2) over its limit, by more than the tolerance (exceedsLimit)?
    bool overLimit(const Spring& s, float len2) const { return overLimit(flags_[s.a] | flags_[s.b], s.rest, len2); }
    // The same from the ends' flags (or-ed) and the rest length.
    bool overLimit(uint8_t endFlags, float rest, float len2) const {
        return exceedsLimit(endFlags, rest, len2, doneRatio_, heldDone_);
    }
    // The ratio at which spring s tears (tearStrainFor): a hem first, then a weak end.
    float tearRatioOf(const Spring& s) const {
        const uint8_t f = flags_[s.a] | flags_[s.b];
        if (f & kHem) return ctx_.hemRatio;
        if (f & (kWeak | kHinge)) return ctx_.weakRatio;
        // By the gauge (tearsOverGauge): at the latest where the limit lets go of it.
        return byGauge(f) ? held_(s.rest) / s.rest : ctx_.tearRatio;
    }
    // Is a spring whose ends' flags (or-ed) are f, neither a hem's nor a tear's, torn by its gauge
    // (tearsOverGauge)? Under a ball, and wherever the limit is a hard cap (no hand moves): a spring
    // a ball held past the threshold is then pulled back, not torn, when the ball lets go of it
    // (at 144 a side its contact flickered and ball-r2-v3 tore that way). Under a moving hand the
    // threshold is the spring's own strain, as before (the drag and pull outcomes).
    bool byGauge(uint8_t f) const { return ctx_.tearing && ((f & kTouched) || holdsOvershoot_); }
    // Did this sub-step's motion alone carry spring s from within the limit past its threshold (see
    // the top of this file)? Read only for springs over a threshold: a few per sub-step at most.
    // The limit is a hard cap here: no hand moves, no ball touches the spring, it touches no tear's
    // tip or hinge (the exceptions of issue 12 goal 5).
    bool hardCap(const Spring& s) const {
        return holdsOvershoot_ && !underBall(s) && !((flags_[s.a] | flags_[s.b]) & (kWeak | kHinge));
    }
    // A spring shorter than the gauge and past the tear threshold tears (byGauge) when the mean
    // strain of the straightest line of springs through it, tear.gauge_length long (or as long
    // as the cloth allows), reaches the threshold; it is held at most at the stretch of a gauge
    // whose other springs are at the limit (heldLength), and tears there.
    bool tearsOverGauge(const Spring& s, float len2) const {
        const uint8_t f = flags_[s.a] | flags_[s.b];
        if (!ctx_.limiting || !byGauge(f) || (f & (kHem | kWeak | kHinge)) || !(s.rest < ctx_.tearGauge)) return false;
        if (len2 < sq(s.rest * ctx_.tearRatio)) return false;
        return gaugeStrain(C_, cloth_, Index(&s - springs_), ctx_.tearGauge) >= ctx_.tearRatio - 1.f;
    }
    bool overshotFromWithinLimit(const Spring& s) const {
        if (!hardCap(s)) return false;
        const Vec3 start = (x_[s.b] - v_[s.b] * ctx_.dt) - (x_[s.a] - v_[s.a] * ctx_.dt);
        return start.squaredNorm() <= sq(s.rest * doneRatio_);
    }
    // A tear candidate of this sub-step, left to the tear phase. A spring too short to halve is
    // limited even as a candidate: if its tear fails (no weak-point path, too short for a basic
    // tear) it must not stay overstretched. Where the limit is a hard cap (hardCap), only the scan's
    // candidates: a spring the passes push past its threshold is limited like any other. It was
    // left unlimited and untorn, and the next sub-step tore it from there, past the overshoot rule
    // (a 2 m cloth pinned left at 65 a side: the passes took a bottom-edge spring from 0.343 to 0.363
    // and converged around it). Under a moving hand or a ball the hand's or the ball's load that the
    // passes push onto a spring past its threshold still tears it (the drag and ball outcomes).
    bool exempt(const Spring& s, float len2) const {
        if (!candidate_[&s - springs_] && hardCap(s)) return false;
        if (len2 < sq(s.rest * minTearRatio_) || s.rest < minTearSplitRest_) return false;
        return len2 >= sq(s.rest * tearRatioOf(s)) &&
               std::sqrt(len2) / s.rest - 1.f >= exemptStrain_ && !heldByLimit(s);
    }
    // A spring over its threshold that the scan kept off the candidates (its held lists: a few
    // springs at most) is limited: a flap's spoke (no one-point split would set the flap loose) or
    // a one-step overshoot (overshotFromWithinLimit).
    bool heldByLimit(const Spring& s) const {
        const Index i = Index(&s - springs_);
        for (const std::vector<Index>& held : T_.held)
            if (std::find(held.begin(), held.end(), i) != held.end()) return true;
        return false;
    }

    // A tether holds its particle within this ratio of its path's rest length (tethers.h).
    float tetherReachRatio() const { return ctx_.maxRatio * (1.f - kTetherSlack); }
    void scan(int t, int nt);
    void prepareTethers(int nt);
    void pullTethers(int t, int nt, bool anyFound);
    void passes(int t, int nt);
    // Gauss-Seidel on several threads (regionPasses): each pass splits the listed springs by region.
    void regionPasses(int t, int nt);
    // This thread's list counted by bin of rest position (LimitCache::regionBin, of each spring's
    // end a) into regionHist_[t], and its size into listSize_[t].
    void countByBin(int t, const SpringList& list);
    uint32_t binOf(Index p) const { return regionBin_[p]; }
    // After a pass's last barrier: did no thread correct a spring (the passes stop)? The last
    // allowed pass's count is what the cap left over (cappedSprings).
    bool correctedNothing(int t, int nt, int pass);
    // After the passes: the springs still listed (iteration cap, exempt candidates) leave the lists.
    void leaveLists(int nt, const SpringList& list);
    // A Jacobi pass is two sweeps over the lists. Sweep 1 (countPass) drops the springs back within
    // the limit and counts the corrections each particle gets (into buffer c). Sweep 2 (correctPass)
    // adds the corrections, each spring's divided by the larger total count of its ends (over all
    // `nc` count buffers).
    int countPass(SpringList& list, Corr* c, std::vector<Index>& touched);
    void correctPass(const SpringList& list, Corr* c, Corr* cv, int nc);
    // A Gauss-Seidel pass: each listed spring over the limit is corrected in place, in list order
    // or backwards (symmetric Gauss-Seidel: a pull travels the whole list in one pass either way);
    // the particles it moves go on `moved` (stamped).
    int gaussSeidelPass(SpringList& list, bool backwards, uint32_t stamp, std::vector<Index>& moved);
    // Lists the springs of the particles in `moved` that a pass pushed over the limit. A spring
    // whose two ends both moved is listed from its lower-numbered end only. `alone`: no other
    // thread lists at the same time (then the AVX2 kernel may run: limit_expand.h).
    void expand(const std::vector<Index>& moved, uint32_t stamp, SpringList& list, bool alone);
    bool prefilterPays(size_t totalMoved) const;
    size_t countMaybeOver(int t, int nt) const;

    const StepContext& ctx_;
    Cloth& cloth_;
    StepState& state_;
    LimitCache& C_;
    ThreadBuffers& T_;
    const CorrectionParams P_;
    const int iterations_;
    const float doneRatio_, minTearRatio_, minTearSplitRest_;
    const HeldLength held_, heldDone_; // under a ball: the length held (heldLength), and with the tolerance
    const bool useTethers_;
    const bool gaussSeidel_;
    const bool holdsOvershoot_; // the limit holds a spring's one-step overshoot (no driver moves)
    // The two exact skips (the tethers, expand after them); CLOTHTEAR_LIMIT_SKIPS=0 turns them off,
    // for the test that they change no bit.
    const bool skipsAllowed_;
    const bool regions_; // limitRegionsAllowed
    // expand may run the AVX2 listing (limit_expand.h): the CPU has it. touched_: LimitCache::touched
    // where a particle is under a ball or in the stretch band this sub-step, else null.
    const bool listingAvx2_;
    const uint8_t* touched_;
    const uint32_t stamp0_;
    Vec3* x_;
    Vec3* v_;
    const float* invMass_;
    const uint8_t* flags_;
    const Spring* springs_;
    uint8_t* listed_;
    uint8_t* candidate_; // per spring: in found[] this sub-step (exempt from the passes)
    uint32_t* movedIn_;
    float exemptStrain_ = -1.f; // with too many candidates: those below this strain are limited
    size_t listSize_[kMaxThreadSlots] = {};
    // Per thread: did the scan see a structural spring longer than tetherReachRatio() x (1 -
    // kTetherBoundMargin) x rest? If no thread did, no tether can pull this sub-step (pullTethers).
    bool tethersMayPull_[kMaxThreadSlots] = {};
    size_t movedCount_[kMaxThreadSlots] = {};       // particles this thread's tethers moved
    size_t overAfterTethers_[kMaxThreadSlots] = {}; // countMaybeOver of this thread's springs
    int work_[kMaxThreadSlots] = {};
    // regionPasses: each thread's list counted by bin of rest position (LimitCache::regionBin); the
    // regions are runs of bins.
    static constexpr uint32_t kRegionBins = LimitCache::kRegionBins;
    const uint8_t* regionBin_ = nullptr;
    // Not zero-filled: written by countByBin before it is read (16 KB, every sub-step).
    uint32_t regionHist_[kMaxThreadSlots][kRegionBins];
};

LimitSolve::LimitSolve(const StepContext& ctx, Cloth& cloth, StepState& state)
    : ctx_(ctx), cloth_(cloth), state_(state), C_(state.limit), T_(state.threads),
      P_{ctx.settings->limit.relaxation, ctx.dt, ctx.velocityFix},
      iterations_(passCap(ctx, cloth, state.limit, !state.contacts.empty())), doneRatio_(ctx.maxRatio * (1.f + kLimitTolerance)),
      minTearRatio_(std::min(ctx.tearRatio, ctx.weakRatio)),
      minTearSplitRest_(minTearSplitRest(cloth)), held_(heldLength(ctx, 1.f)), heldDone_(heldLength(ctx, 1.f + kLimitTolerance)),
      useTethers_(ctx.limiting),
      gaussSeidel_(ctx.settings->limit.solver == LimitSolver::GaussSeidel),
      holdsOvershoot_(ctx.limiting && !driversMove(*ctx.drivers)), skipsAllowed_(limitSkipsAllowed()),
      regions_(limitRegionsAllowed()),
      listingAvx2_(ctx.limiting && listingAvx2Available()),
      touched_(state.contacts.empty() && state.stretchBand.empty() ? nullptr : state.limit.touched.data()),
      stamp0_(state.limit.passStamp), x_(cloth.x.data()), v_(cloth.v.data()), invMass_(cloth.invMass.data()),
      flags_(cloth.flags.data()), springs_(cloth.springs.data()),
      listed_(ctx.limiting ? state.limit.listed.data() : nullptr),
      candidate_(ctx.limiting ? state.limit.candidate.data() : nullptr),
      movedIn_(ctx.limiting ? state.limit.moved.data() : nullptr) {
    if (ctx.limiting) C_.passStamp += uint32_t(iterations_) + 1; // the passes', then the tethers' stamp
    regionBin_ = state.limit.regionBin.data();
}

// Every structural spring once, most of them with one compare and no square root: tear candidates
// into found[t], springs over the limit onto this thread's list.
void LimitSolve::scan(int t, int nt) {
    const SpringCache& S = state_.springs;
    const SpringArrays arrays = springArraysOf(S);
    // The scan flags springs over the limit and those over a tear threshold (which may be lower).
    const float scanRatio = std::min(ctx_.limiting ? doneRatio_ : 1e30f, minTearRatio_);
    SpringList& list = T_.active[t];
    std::vector<TearCandidate>& found = T_.found[t];
    const Chunk sc = chunkOf(cloth_.springs.size(), t, nt);
    // Read only where the tethers pull (pullTethers).
    const float watchRatio = tetherReachRatio() * (1.f - kTetherBoundMargin);
    const PackedParticle* packed = state_.packed.data();
    tethersMayPull_[t] = scanSprings(arrays, sc.begin, sc.end, scanRatio, watchRatio, packed, [&](size_t e, float len2) {
        const Index i = S.index[e];
        const Spring& s = springs_[i];
        if (len2 >= sq(s.rest * minTearRatio_) && (len2 >= sq(s.rest * tearRatioOf(s)) || tearsOverGauge(s, len2))) {
            if ((((flags_[s.a] | flags_[s.b]) & kHinge) && isFlapSpoke(cloth_, Index(i))) || overshotFromWithinLimit(s))
                T_.held[t].push_back(Index(i));
            else {
                found.push_back(TearCandidate{Index(i), std::sqrt(len2) / s.rest - 1.f});
                if (candidate_) candidate_[i] = 1;
            }
        }
        if (ctx_.limiting && overLimit(s, len2)) {
            listed_[i] = 1;
            list.push_back(Index(i));
        }
    });
}

// Thread 0, after the scan: the tethers that must not pull (their path runs through a candidate or a
// particle under a ball: what hangs below a ball hangs from it), and with more candidates than
// tear.max_per_step, the strain below which candidates are limited after all.
void LimitSolve::prepareTethers(int nt) {
    const int maxPerStep = ctx_.settings->tear.maxPerStep;
    size_t candidates = 0;
    for (int k = 0; k < nt; ++k) candidates += T_.found[k].size();
    if (useTethers_) {
        std::vector<Index> seeds;
        for (int k = 0; k < nt; ++k)
            for (const TearCandidate& f : T_.found[k]) {
                seeds.push_back(springs_[f.spring].a);
                seeds.push_back(springs_[f.spring].b);
            }
        for (const BallContact& c : state_.contacts)
            for (Index p : cloth_.triangles[c.triangle].p) seeds.push_back(p);
        seeds.insert(seeds.end(), state_.stretchBand.begin(), state_.stretchBand.end());
        for (TetherSet& set : C_.tethers) markTethersThrough(set, seeds);
    }
    if (candidates > size_t(maxPerStep)) {
        std::vector<float> strains;
        for (int k = 0; k < nt; ++k)
            for (const TearCandidate& f : T_.found[k]) strains.push_back(f.strain);
        std::nth_element(strains.begin(), strains.begin() + (maxPerStep - 1), strains.end(), std::greater<>());
        exemptStrain_ = strains[maxPerStep - 1];
    }
}

// The tethers of this thread's particles: their anchors are pinned, so nothing another thread does
// moves what this one reads. With no candidates and no contacts (`anyFound` false) every tether pulls.
void LimitSolve::pullTethers(int t, int nt, bool anyFound) {
    if (!useTethers_) return;
    // Skipped by every thread alike when no structural spring is past the tethers' reach ratio:
    // a tether spans a path of springs, so its particle is then within reach (scan()).
    bool mayPull = !skipsAllowed_;
    for (int k = 0; k < nt; ++k) mayPull |= tethersMayPull_[k];
    if (!mayPull) {
        if (t == 0) tethersSkipped = true;
        return;
    }
    const Chunk pc = chunkOf(cloth_.particleCount(), t, nt);
    // A tether's pull can stretch the particle's other springs past the limit (sideways, towards
    // another anchor): the passes must see them. The scan read the positions before the pull.
    std::vector<Index>& moved = T_.moved[t];
    moved.clear();
    PackedParticle* packed = state_.packed.data();
    for (const TetherSet& set : C_.tethers) {
        if (set.order.empty()) continue;
        const size_t first = moved.size();
        tetherKernel(pc.begin, pc.end, set.tether.data(), set.length.data(), anyFound ? set.cut.data() : nullptr,
                     tetherReachRatio(), ctx_.dt, ctx_.velocityFix, packed, x_, v_, moved);
        // The next set reads where this one put them (a thread moves only its own particles; the
        // anchors are pinned).
        for (size_t k = first; k < moved.size(); ++k) {
            const Index p = moved[k];
            packed[p] = packedOf(x_[p], v_[p]);
        }
    }
    // A particle two sets moved is listed once: expand looks at each moved particle's springs.
    const uint32_t stamp = stamp0_ + uint32_t(iterations_) + 1;
    size_t keep = 0;
    for (Index p : moved)
        if (movedIn_[p] != stamp) {
            movedIn_[p] = stamp;
            moved[keep++] = p;
        }
    moved.resize(keep);
    movedCount_[t] = keep;
    parallelBarrier(nt); // stamps and counts complete (expand reads the other end's)
    size_t totalMoved = 0;
    for (int k = 0; k < nt; ++k) totalMoved += movedCount_[k];
    if (prefilterPays(totalMoved)) {
        overAfterTethers_[t] = countMaybeOver(t, nt);
        parallelBarrier(nt); // counts complete
        size_t over = 0;
        for (int k = 0; k < nt; ++k) over += overAfterTethers_[k];
        if (over == 0) { // expand would list nothing
            if (t == 0) expandSkipped = true;
            return;
        }
        if (t == 0) prefilterFailed = true;
    }
    expand(moved, stamp, T_.active[t], nt == 1);
}

// The tethers moved `totalMoved` particles; expand reads the structural springs of each (about six,
// each spring from both ends) through the particle-spring table, scattered. When the tethers moved
// much of the cloth (a cloth hanging on them: the 6 m scenes, a hand's pull, a 128 x 128 curtain at
// 1/600 s, where expand was 27 % of the sub-step), one pass of the scan's kernel over every spring,
// in memory order and four at a time, usually finds that none of them is over the limit, and
// expand is skipped.
// After a sub-step whose scan found springs over, the next kPrefilterWait do not try.
bool LimitSolve::prefilterPays(size_t totalMoved) const {
    return skipsAllowed_ && C_.prefilterWait == 0 && 4 * totalMoved >= cloth_.particleCount();
}

// How many of this thread's share of the structural springs, not on a list yet, may be over the
// limit after the tethers pulled. The bar is the lower of the two limits less kPrefilterMargin, far
// above the round-off between the kernel's squared length (from the packed copy, which the tethers
// keep equal to x) and overLimit's: a spring expand would list is always counted, so a count of 0
// over all threads means expand would list nothing.
size_t LimitSolve::countMaybeOver(int t, int nt) const {
    const SpringCache& S = state_.springs;
    const SpringArrays arrays = springArraysOf(S);
    const float bar = std::min(doneRatio_, heldDone_.minRatio()) * (1.f - kPrefilterMargin);
    const Chunk sc = chunkOf(cloth_.springs.size(), t, nt);
    size_t count = 0;
    scanSprings(arrays, sc.begin, sc.end, bar, 0.f, state_.packed.data(),
                [&](size_t e, float) { count += listed_[S.index[e]] == 0; });
    return count;
}

int LimitSolve::countPass(SpringList& list, Corr* c, std::vector<Index>& touched) {
    int corrected = 0;
    size_t keep = 0;
    for (Index i : list) {
        const Spring& s = springs_[i];
        const float len2 = (x_[s.b] - x_[s.a]).squaredNorm();
        if (!overLimit(s, len2)) {
            listed_[i] = 0;
            continue;
        }
        list[keep++] = i;
        if (!exempt(s, len2)) corrected += countCorrection(s, invMass_, c, touched);
    }
    list.resize(keep);
    return corrected;
}

void LimitSolve::correctPass(const SpringList& list, Corr* c, Corr* cv, int nc) {
    auto& corr = T_.corr;
    for (Index i : list) {
        const Spring& s = springs_[i];
        if (invMass_[s.a] + invMass_[s.b] == 0.f) continue;
        const Vec3 d = x_[s.b] - x_[s.a];
        const float len2 = d.squaredNorm();
        if (exempt(s, len2)) continue;
        float ca = 0.f, cb = 0.f;
        for (int k = 0; k < nc; ++k) {
            ca += corr[k][s.a].w();
            cb += corr[k][s.b].w();
        }
        addCorrection(s, d, len2, underBall(s) ? held_(s.rest) : s.rest * ctx_.maxRatio, std::max(ca, cb), invMass_,
                      v_, P_, c, cv);
    }
}

int LimitSolve::gaussSeidelPass(SpringList& list, bool backwards, uint32_t stamp, std::vector<Index>& moved) {
    int corrected = 0;
    const size_t count = list.size();
    for (size_t j = 0; j < count; ++j) {
        const Index i = list[backwards ? count - 1 - j : j];
        const Spring& s = springs_[i];
        const Vec3 d = x_[s.b] - x_[s.a];
        const float len2 = d.squaredNorm();
        if (!overLimit(s, len2)) {
            listed_[i] = 0;
            continue;
        }
        const float wa = invMass_[s.a], wb = invMass_[s.b];
        if (wa + wb == 0.f || exempt(s, len2)) continue;
        const float maxLen = underBall(s) ? held_(s.rest) : s.rest * ctx_.maxRatio;
        const LimitMove m = limitMove(s, d, len2, maxLen, 1.f, invMass_, v_, P_);
        x_[s.a] += wa * m.c;
        v_[s.a] += wa * m.dv;
        x_[s.b] -= wb * m.c;
        v_[s.b] -= wb * m.dv;
        ++corrected;
        for (Index p : {s.a, s.b})
            if (invMass_[p] > 0.f && movedIn_[p] != stamp) {
                movedIn_[p] = stamp;
                moved.push_back(p);
            }
    }
    list.erase(std::remove_if(list.begin(), list.end(), [&](Index i) { return listed_[i] == 0; }), list.end());
    return corrected;
}

void LimitSolve::expand(const std::vector<Index>& moved, uint32_t stamp, SpringList& list, bool alone) {
    // overLimit, from the particle-spring table's other end and rest length: the spring itself is
    // not read (|x_q - x_p|^2 is |x_b - x_a|^2 to the bit).
    // Members in locals: the byte stores into `listed` may alias anything, and the compiler
    // reloaded every member after each of them.
    const uint32_t* start = C_.springStart.data();
    const Index* endSpring = C_.endSpring.data();
    const Index* endOther = C_.endOther.data();
    const float* endRest = C_.endRest.data();
    const Vec3* x = x_;
    const uint8_t* flags = flags_;
    const uint32_t* movedIn = movedIn_;
    uint8_t* listed = listed_;
    const float done = doneRatio_;
    const HeldLength heldDone = heldDone_;
    // Without branches: whether a spring goes on the list is data (about half of those looked at
    // under a moving hand), and mispredicted branches were most of this loop's time. Every spring
    // of p is written past the list's end and the count moves on by the ones taken. Within one
    // call no spring is taken from both ends (`fromOtherEnd`), so `listed` reads here as it read
    // with a branch on each test in turn.
    // Room for every spring of every moved particle, made once (a resize per particle checked the
    // capacity each time), and not zero-filled (SpringList): only what is taken is read.
    size_t n = list.size(), room = 0;
    uint8_t sink = 0; // where a spring not taken writes its flag
    for (Index p : moved) room += start[p + 1] - start[p];
    if (listingAvx2_ && alone) {
#ifndef NDEBUG
        for (Index p : moved) // the kernel reads kTouched from LimitCache::touched (phaseLimit)
            for (uint32_t k = start[p]; k < start[p + 1]; ++k) {
                const Index q = endOther[k];
                assert(bool((flags[p] | flags[q]) & kTouched) == (touched_ && (touched_[p] | touched_[q])));
            }
#endif
        list.resize(n + room + 8); // the kernel stores eight entries at a time
        const ListingArrays arrays{start, endSpring, endOther, endRest, x, movedIn, listed, done, touched_, heldDone};
        list.resize(listAvx2(arrays, moved.data(), moved.size(), stamp, list.data(), n));
        listingsAvx2 += !moved.empty();
        return;
    }
    list.resize(n + room);
    Index* out = list.data();
    for (Index p : moved) {
        const Vec3 xp = x[p];
        const uint8_t fp = flags[p];
        const uint32_t k0 = start[p], k1 = start[p + 1];
        for (uint32_t k = k0; k < k1; ++k) {
            const Index i = endSpring[k], q = endOther[k];
            const bool fromOtherEnd = (q < p) & (movedIn[q] == stamp);
            const bool over = exceedsLimit(fp | flags[q], endRest[k], (x[q] - xp).squaredNorm(), done, heldDone);
            // Relaxed atomics (plain byte moves): under regionPasses the thread that moved q may be
            // taking this spring now, from its end; this one reads the flag but writes it only if it
            // takes the spring (a write back of the flag read would undo the other thread's).
            const bool take = (std::atomic_ref<uint8_t>(listed[i]).load(std::memory_order_relaxed) == 0) &
                              !fromOtherEnd & over;
            out[n] = i;
            std::atomic_ref<uint8_t>(take ? listed[i] : sink).store(1, std::memory_order_relaxed);
            n += take;
        }
    }
    list.resize(n);
}

// Jacobi passes over the listed springs, until none is over the limit or limit.iterations ran.
void LimitSolve::passes(int t, int nt) {
    auto& active = T_.active;
    auto& corr = T_.corr;
    auto& corrV = T_.corrV;
    auto& touched = T_.touched;
    auto& moved = T_.moved;
    SpringList& list = active[t];
    const Chunk pc = chunkOf(cloth_.particleCount(), t, nt);
    if (gaussSeidel_ && nt > 1) {
        if (regions_) return regionPasses(t, nt);
        // One list: the threads' lists in thread order.
        parallelBarrier(nt);
        if (t == 0)
            for (int k = 1; k < nt; ++k) {
                active[0].insert(active[0].end(), active[k].begin(), active[k].end());
                active[k].clear();
            }
    }
    for (int pass = 0; pass < iterations_; ++pass) {
        const uint32_t stamp = stamp0_ + uint32_t(pass) + 1;
        // After the last allowed pass nothing reads the lists but to empty them: no expand (under a
        // moving hand every sub-step runs to the cap, and expand costs several times the pass).
        const bool another = pass + 1 < iterations_;
        listSize_[t] = list.size();
        parallelBarrier(nt); // lists, positions and listSize_[] complete
        size_t total = 0;
        for (int k = 0; k < nt; ++k) total += listSize_[k];
        if (total == 0) break;
        if (t == 0) passesRun = pass + 1;
        if (gaussSeidel_) {
            // Gauss-Seidel: thread 0, in place (its corrections read the ones before them).
            if (t == 0) {
                moved[0].clear();
                work_[0] = gaussSeidelPass(active[0], pass % 2 == 1, stamp, moved[0]);
                if (another) expand(moved[0], stamp, active[0], true);
                for (int k = 1; k < nt; ++k) work_[k] = 0;
            }
        } else if (total < kSerialList || nt == 1) {
            // Thread 0 works every list, in thread order, into its own buffer.
            if (t == 0) {
                int corrected = 0;
                touched[0].clear();
                for (int k = 0; k < nt; ++k) corrected += countPass(active[k], corr[0].data(), touched[0]);
                for (int k = 0; k < nt; ++k) correctPass(active[k], corr[0].data(), corrV[0].data(), 1);
                moved[0].clear();
                applyCorrections(touched, corr, corrV, 1, [](Index) { return true; }, x_, v_, movedIn_, stamp,
                                 moved[0]);
                if (another) expand(moved[0], stamp, active[0], true);
                work_[0] = corrected;
                for (int k = 1; k < nt; ++k) work_[k] = 0;
            }
        } else {
            touched[t].clear();
            work_[t] = countPass(list, corr[t].data(), touched[t]);
            parallelBarrier(nt); // counts complete
            correctPass(list, corr[t].data(), corrV[t].data(), nt);
            parallelBarrier(nt); // corrections complete
            moved[t].clear();
            auto mine = [&](Index p) { return p >= pc.begin && p < pc.end; };
            applyCorrections(touched, corr, corrV, nt, mine, x_, v_, movedIn_, stamp, moved[t]);
            parallelBarrier(nt); // positions and stamps complete
            if (another) expand(moved[t], stamp, list, false);
        }
        parallelBarrier(nt); // work_[] complete
        if (correctedNothing(t, nt, pass)) break;
    }
    leaveLists(nt, list);
}

bool LimitSolve::correctedNothing(int t, int nt, int pass) {
    int corrected = 0;
    for (int k = 0; k < nt; ++k) corrected += work_[k];
    if (corrected == 0) return true;
    if (t == 0 && pass + 1 == iterations_) cappedSprings = corrected;
    return false;
}

void LimitSolve::leaveLists(int nt, const SpringList& list) {
    parallelBarrier(nt);
    for (Index i : list) listed_[i] = 0;
}

void LimitSolve::countByBin(int t, const SpringList& list) {
    uint32_t* hist = regionHist_[t];
    std::fill(hist, hist + kRegionBins, 0u);
    for (Index i : list) ++hist[binOf(springs_[i].a)];
    listSize_[t] = list.size();
}

// Gauss-Seidel passes on nt threads. On one thread a pass corrects the listed springs in place, one
// after the other; under a moving hand every sub-step runs its passes to the cap on lists of a few
// hundred springs, and on two threads the other thread waited through them (the window's 128 x 128
// drag spent most of its limit phase there: bench/README.md, "Gauss-Seidel by regions"). Here a pass
// splits the cloth into nt regions, runs of bins of rest position (LimitCache::regionBin) chosen
// from the lists so that each gets about as many springs, and thread r corrects, in place and in
// list order (the threads' lists in thread order), the springs whose two ends are both in region r:
// no two threads move the same particle. Then thread 0 corrects the springs that join two regions.
// Backwards passes run each region's springs backwards. A list shorter than kRegionMinList is one
// region, thread 0's (two barriers a pass, as the one-thread order had). The order is a function
// of the lists alone, so the result is the same run after run for a thread count: the one-thread
// order up to springs that share no particle, but for the joining springs, which come last (as the
// spring forces' sums are another order of the same floats on two threads). A spring is listed
// again by the thread that moved its lower-numbered moved end (expand), so by one thread.
void LimitSolve::regionPasses(int t, int nt) {
    SpringList& list = T_.active[t];
    std::vector<SpringList>& mine = T_.regionLists[t]; // this thread's list by region, then joining two
    std::vector<Index>& moved = T_.moved[t];
    const size_t joining = size_t(nt);
    countByBin(t, list);
    parallelBarrier(nt); // lists counted
    for (int pass = 0; pass < iterations_; ++pass) {
        const uint32_t stamp = stamp0_ + uint32_t(pass) + 1;
        const bool another = pass + 1 < iterations_;
        const bool backwards = pass % 2 == 1;
        size_t total = 0;
        for (int k = 0; k < nt; ++k) total += listSize_[k];
        if (total == 0) break;
        if (t == 0) passesRun = pass + 1;
        // The regions, the same on every thread: runs of bins of about total / nt springs each.
        const bool split = total >= kRegionMinList;
        if (t == 0) regionPassesRun += split;
        uint8_t regionOfBin[kRegionBins] = {};
        if (split) {
            uint64_t counted = 0;
            int r = 0;
            for (uint32_t b = 0; b < kRegionBins; ++b) {
                regionOfBin[b] = uint8_t(r);
                for (int k = 0; k < nt; ++k) counted += regionHist_[k][b];
                while (r + 1 < nt && counted * uint64_t(nt) >= total * uint64_t(r + 1)) ++r;
            }
        }
        for (SpringList& l : mine) l.clear();
        for (Index i : list) {
            const uint8_t ra = regionOfBin[binOf(springs_[i].a)], rb = regionOfBin[binOf(springs_[i].b)];
            mine[ra == rb ? ra : joining].push_back(i);
        }
        parallelBarrier(nt); // every list split
        moved.clear();
        int corrected = 0;
        for (int j = 0; j < nt; ++j) {
            const int k = backwards ? nt - 1 - j : j;
            corrected += gaussSeidelPass(T_.regionLists[k][t], backwards, stamp, moved);
        }
        if (split) {
            parallelBarrier(nt); // the regions corrected
            if (t == 0)
                for (int j = 0; j < nt; ++j) {
                    const int k = backwards ? nt - 1 - j : j;
                    corrected += gaussSeidelPass(T_.regionLists[k][joining], backwards, stamp, moved);
                }
            parallelBarrier(nt); // the joining springs corrected: positions and stamps complete
        }
        // (One region: the other threads had nothing to correct, and read nothing thread 0 wrote
        // until the barrier below.) The springs still listed (gaussSeidelPass dropped the others
        // from their lists), then those the pass pushed over the limit.
        list.clear();
        for (int k = 0; k < nt; ++k) {
            const SpringList& kept = T_.regionLists[k][t];
            list.insert(list.end(), kept.begin(), kept.end());
        }
        if (t == 0)
            for (int k = 0; k < nt; ++k) {
                const SpringList& kept = T_.regionLists[k][joining];
                list.insert(list.end(), kept.begin(), kept.end());
            }
        if (another) expand(moved, stamp, list, false);
        countByBin(t, list);
        work_[t] = corrected;
        parallelBarrier(nt); // work_[], lists and their counts complete
        if (correctedNothing(t, nt, pass)) break;
    }
    leaveLists(nt, list);
}

void LimitSolve::run() {
    const size_t n = cloth_.particleCount(), ns = cloth_.springs.size();
    parallelRegion(std::max(ns, n), int(T_.acc.size()), [&](int t, int nt) {
        scan(t, nt);
        if (!ctx_.limiting) return;
        parallelBarrier(nt); // candidates complete
        size_t candidates = 0;
        for (int k = 0; k < nt; ++k) candidates += T_.found[k].size();
        // Every thread counts the same lists, so all agree on anyFound.
        const bool anyFound = candidates > 0 || !state_.contacts.empty();
        if (anyFound) {
            if (t == 0) prepareTethers(nt);
            parallelBarrier(nt); // cut marks and exemptStrain_ complete
        }
        pullTethers(t, nt, anyFound);
        passes(t, nt);
        for (const TearCandidate& f : T_.found[t]) candidate_[f.spring] = 0; // passes() ends with a barrier
    });
}

// Per-thread work arrays sized for this cloth and emptied for the sub-step.
void prepareBuffers(ThreadBuffers& T, int threads, size_t particles) {
    if (T.corr.size() != size_t(threads)) T.corr.resize(threads);
    if (T.corrV.size() != size_t(threads)) T.corrV.resize(threads);
    for (auto& c : T.corr)
        if (c.size() != particles) c.resize(particles, Corr::Zero());
    for (auto& c : T.corrV)
        if (c.size() != particles) c.resize(particles, Corr::Zero());
    T.active.resize(threads);
    T.regionLists.resize(threads);
    for (auto& r : T.regionLists) r.resize(size_t(threads) + 1);
    T.moved.resize(threads);
    T.touched.resize(threads);
    T.found.resize(threads);
    T.held.resize(threads);
    for (int t = 0; t < threads; ++t) {
        T.active[t].clear();
        T.moved[t].clear();
        T.found[t].clear();
        T.held[t].clear();
    }
}

} // namespace

void phaseLimit(const StepContext& ctx, Cloth& cloth, StepState& state) {
    prepareBuffers(state.threads, int(state.threads.acc.size()), cloth.particleCount());
    if (ctx.limiting) refreshLimitCache(ctx, cloth, state.limit);
    if (ctx.limiting && ctx.settings->limit.solver == LimitSolver::GaussSeidel && state.threads.acc.size() > 1 &&
        state.limit.regionBin.size() != cloth.particleCount())
        buildRegionBins(cloth, state.limit); // regionPasses reads them
    markStretchBand(ctx, cloth, state);
    capTensionUnderBall(ctx, cloth, state);
    // kTouched as bytes for the AVX2 listing (LimitCache::touched), set for the phase.
    std::vector<uint8_t>& touched = state.limit.touched;
    auto markTouched = [&](uint8_t value) {
        if (!ctx.limiting) return;
        for (const BallContact& c : state.contacts)
            for (Index p : cloth.triangles[c.triangle].p) touched[p] = value;
        for (Index p : state.stretchBand) touched[p] = value;
    };
    markTouched(1);
    LimitSolve solve(ctx, cloth, state);
    solve.run();
    markTouched(0);
    // The band lets go; the contacts' own particles keep their mark until the contact phase.
    for (Index p : state.stretchBand) cloth.flags[p] &= uint8_t(~kTouched);
    state.stretchBand.clear();
    ctx.profile->limitPasses += uint64_t(solve.passesRun);
    ctx.profile->limitRegionPasses += uint64_t(solve.regionPassesRun);
    ctx.profile->limitTethersSkipped += solve.tethersSkipped;
    ctx.profile->limitExpandSkipped += solve.expandSkipped;
    ctx.profile->limitListingsAvx2 += uint64_t(solve.listingsAvx2);
    LimitCache& C = state.limit;
    if (solve.prefilterFailed) C.prefilterWait = kPrefilterWait;
    else if (C.prefilterWait > 0) --C.prefilterWait;
    if (solve.cappedSprings > 0) {
        ctx.profile->limitCapped++;
        ctx.profile->limitCappedSprings += uint64_t(solve.cappedSprings);
    }
    // Tear candidates, merged in thread order (deterministic).
    state.tearCandidates.clear();
    for (auto& f : state.threads.found) state.tearCandidates.insert(state.tearCandidates.end(), f.begin(), f.end());
}

} // namespace clothtear
