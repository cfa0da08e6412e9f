// The knife (knife.h): each segment of a stroke is cut in two steps.
//
//   1. Refine: the segment's ends, and every spring it crosses, become particles on it (splitSpring
//      without separation). Splitting every crossed edge of a triangle from its crossing point to the
//      opposite corner leaves the piece of the segment inside that triangle as an edge:
//
//          C                    C             entry X1 on AB, exit X2 on BC: the split of AB
//         / \                  /|\            joins X1 to C; BC then lies in triangle X1-B-C,
//        /   \                / | X2          whose split at X2 joins X2 to X1. The segment is
//       /   _.X2     ->      / .'/ \          the chain of edges ... X1 - X2 ...
//      A--X1-----B          A--X1---B
//
//   2. Separate: at each particle on the chain its fan is divided by the chain's edges (the "cut
//      spokes") into groups, and every group but one moves to a copy of the particle (detachGroup),
//      taking its own copy of each cut spoke it shared. A closed fan with one cut spoke (the end of a
//      cut inside the cloth) stays whole: the edge is opened from its other end, and the particle is
//      left a tear tip (a weak point), as a tear leaves it.
//
// Section index:
//   [PLANE]     rest positions in the stroke's frame
//   [REFINE]    the segment's ends and crossings become particles
//   [CHAIN]     the joined edges along the segment
//   [SEPARATE]  each particle on the segment: its fan divided by the cut spokes
//   [DRIVER]    checks, the stroke segment by segment, events
#include "clothtear/knife.h"

#include "tear_topology.h"

#include <algorithm>
#include <cmath>

namespace clothtear {
namespace {

// A crossing closer to a spring's end than this fraction of the spring goes through the end: the cut
// then bends by at most a tenth of an edge, and the split never makes an edge shorter than a tenth
// of the one it came from (short edges are stiff: the stability guard would pay for them). Points
// inside a triangle are snapped alike by their barycentric coordinates.
constexpr double kSnap = 0.1;
// "Exactly on" up to rounding, relative to the lengths involved: a stroke along a grid line or
// through a particle, given in the same coordinates the mesh was built from.
constexpr double kOn = 1e-9;

double cross(const Vec2d& a, const Vec2d& b) { return a.x() * b.y() - a.y() * b.x(); }

class SegmentCut {
public:
    SegmentCut(Cloth& c, const MeshFrame& frame, std::vector<Vec2d>& at, CutResult& out, const Vec2d& a,
               const Vec2d& b)
        : c_(c), frame_(frame), at_(at), out_(out), a_(a), b_(b), d_(b - a) {}

    void run(const TearContext& ctx) {
        insertPoint(a_);
        insertPoint(b_);
        // Splits append springs that the same pass then sees; they touch the segment only at their
        // new particle, so a second pass finds nothing new (it is there to make sure).
        for (int pass = 0; pass < 3 && crossings(); ++pass) {}
        std::sort(onStroke_.begin(), onStroke_.end());
        onStroke_.erase(std::unique(onStroke_.begin(), onStroke_.end()), onStroke_.end());
        findChain();
        splitLoneEdges();
        // Along the segment (ties by index), so particle numbers follow the stroke.
        std::sort(onStroke_.begin(), onStroke_.end(), [&](Index p, Index q) {
            const double u = param(p), v = param(q);
            return u != v ? u < v : p < q;
        });
        for (Index p : onStroke_) separateAt(p, ctx);
        logCutSprings(ctx);
        validateAfterChange(c_, ctx.settings, ctx.log);
    }

private:
    // ============================================================================================ [PLANE]
    void sync() {
        for (size_t p = at_.size(); p < c_.particleCount(); ++p)
            at_.push_back(Vec2d(frame_.u(c_.rest[p]), frame_.v(c_.rest[p])));
    }
    // Position along the segment: 0 at its start, 1 at its end.
    double param(Index p) const { return (at_[p] - a_).dot(d_) / d_.squaredNorm(); }
    void record(Index p) { onStroke_.push_back(p); }

    // =========================================================================================== [REFINE]
    Index split(Index s, double t) {
        std::vector<Index> touched;
        const SplitEnds m = splitSpring(c_, s, t, false, touched);
        refreshAround(c_, touched);
        sync();
        out_.springsSplit++;
        return m.onA;
    }

    // Makes point e a particle of every triangle that contains it (several where a slit's two walls
    // meet there): a corner near it is taken as it is; near an edge, the edge is split at e's
    // projection; inside, the cevian from the corner nearest e is split in at e's line, then split at
    // e (two splits: the only operation that adds a particle is splitSpring).
    void insertPoint(const Vec2d& e) {
        for (int round = 0; round < 16; ++round) {
            // Barycentric coordinates of e in every triangle that holds it.
            struct Holder {
                Triangle T;
                double l[3];
                int top;
            };
            std::vector<Holder> holders;
            std::vector<Index> corners;
            for (Index t = 0; t < c_.triangles.size(); ++t) {
                const Triangle& T = c_.triangles[t];
                const Vec2d &p0 = at_[T.p[0]], &p1 = at_[T.p[1]], &p2 = at_[T.p[2]];
                const double area = cross(p1 - p0, p2 - p0);
                if (!(std::abs(area) > 1e-14 * (p1 - p0).squaredNorm())) continue; // edge-on in the plane
                Holder h{T, {cross(p1 - e, p2 - e) / area, cross(p2 - e, p0 - e) / area, cross(p0 - e, p1 - e) / area}, 0};
                if (h.l[0] < -kOn || h.l[1] < -kOn || h.l[2] < -kOn) continue;
                h.top = int(std::max_element(h.l, h.l + 3) - h.l);
                if (std::count_if(h.l, h.l + 3, [](double x) { return x < kSnap; }) >= 2) corners.push_back(T.p[h.top]);
                holders.push_back(h);
            }
            // A triangle around a corner taken is done (in a thin one the same point may look merely
            // near an edge); any other holder gets a particle at e, then the holders are found again.
            const Holder* open = nullptr;
            for (const Holder& h : holders) {
                const bool done = std::any_of(std::begin(h.T.p), std::end(h.T.p), [&](Index p) {
                    return std::find(corners.begin(), corners.end(), p) != corners.end();
                });
                if (!done) {
                    open = &h;
                    break;
                }
            }
            if (!open) {
                for (Index p : corners) record(p);
                return;
            }
            const Triangle& T = open->T;
            const double* l = open->l;
            // The edge opposite a corner joins p[corner+1] and p[corner+2] (slot corner+1); e's point on it.
            auto splitOpposite = [&](int corner) {
                const int i1 = (corner + 1) % 3, i2 = (corner + 2) % 3;
                const Index s = T.s[i1];
                const double f = l[i2] / (l[i1] + l[i2]); // from p[i1] towards p[i2]
                return split(s, c_.springs[s].a == T.p[i1] ? f : 1.0 - f);
            };
            const int near = int(std::min_element(l, l + 3) - l);
            if (l[near] < kSnap) {
                record(splitOpposite(near)); // near an edge: onto it
            } else {
                const Index f = splitOpposite(open->top), corner = T.p[open->top];
                const Index s = findSpring(c_, corner, f);
                const double along = 1.0 - l[open->top]; // e = corner + along * (f - corner)
                record(split(s, c_.springs[s].a == corner ? along : 1.0 - along));
            }
        }
    }

    // One pass over the springs: each one the segment crosses is split there, or its end taken when
    // the crossing is near it; springs lying on the segment's line give their ends. Returns whether
    // anything was split.
    bool crossings() {
        const double len = d_.norm();
        const Vec2d lo = a_.cwiseMin(b_).array() - kOn * len, hi = a_.cwiseMax(b_).array() + kOn * len;
        bool splitAny = false;
        for (Index s = 0; s < c_.springs.size(); ++s) {
            const Index pa = c_.springs[s].a, pb = c_.springs[s].b;
            const Vec2d p = at_[pa], e = at_[pb] - p;
            if (std::max(p.x(), p.x() + e.x()) < lo.x() || std::min(p.x(), p.x() + e.x()) > hi.x() ||
                std::max(p.y(), p.y() + e.y()) < lo.y() || std::min(p.y(), p.y() + e.y()) > hi.y())
                continue;
            const double elen = e.norm(), den = cross(d_, e);
            const Vec2d w = p - a_;
            if (std::abs(den) <= kOn * len * elen) { // parallel: on the line, the ends within the segment count
                if (std::abs(cross(d_, w)) > kOn * len * std::max(len, elen)) continue;
                for (Index q : {pa, pb})
                    if (const double u = param(q); u >= -kOn && u <= 1 + kOn) record(q);
                continue;
            }
            const double u = cross(w, e) / den, t = cross(w, d_) / den;
            if (u < -kOn || u > 1 + kOn || t < -kOn || t > 1 + kOn) continue;
            // A spring already short (minSplitRest, the tear's own floor) is not split again.
            const double snap = std::max(kSnap, 0.5 * double(c_.minSplitRest) / std::max(1e-30, double(c_.springs[s].rest)));
            if (t <= std::min(snap, 0.5)) record(pa);
            else if (t >= 1.0 - snap) record(pb);
            else record(split(s, t)), splitAny = true;
        }
        return splitAny;
    }

    // ============================================================================================ [CHAIN]
    bool inChain(Index s) const { return std::binary_search(chain_.begin(), chain_.end(), s); }
    bool isCutSpoke(Index s) const { return c_.springTopo[s].tri[1] != kNone && inChain(s); }

    // The joined springs with both ends on the segment. Where three particles on it make a sliver
    // triangle, its long side is not one of them (the chain runs through the third corner).
    void findChain() {
        std::vector<uint8_t> on(c_.particleCount(), 0);
        for (Index p : onStroke_) on[p] = 1;
        const double margin = kOn;
        for (Index p : onStroke_)
            for (Index t : c_.particleTris[p])
                for (Index s : c_.triangles[t].s) {
                    const Spring& sp = c_.springs[s];
                    const SpringTopo& topo = c_.springTopo[s];
                    if (!on[sp.a] || !on[sp.b] || topo.tri[1] == kNone) continue;
                    const double lo = std::min(param(sp.a), param(sp.b)) + margin,
                                 hi = std::max(param(sp.a), param(sp.b)) - margin;
                    bool longSide = false;
                    for (Index nt : topo.tri) {
                        const Triangle& T = c_.triangles[nt];
                        const Index r = T.p[(edgeSlotOf(T, s) + 2) % 3];
                        longSide |= on[r] && param(r) > lo && param(r) < hi;
                    }
                    if (!longSide) chain_.push_back(s);
                }
        std::sort(chain_.begin(), chain_.end());
        chain_.erase(std::unique(chain_.begin(), chain_.end()), chain_.end());
    }

    // Whether particle v can open edge e: the fan of v holding e is open (a border or a tear reaches
    // v) or holds another cut spoke (v is inside the cut).
    bool opensAt(Index v, Index e) const {
        for (const Fan& f : fansAround(c_, v)) {
            if (std::find(f.spokes.begin(), f.spokes.end(), e) == f.spokes.end()) continue;
            if (!f.closed) return true;
            return std::count_if(f.spokes.begin(), f.spokes.end(), [&](Index s) { return isCutSpoke(s); }) >= 2;
        }
        return false;
    }

    // An edge whose two ends are both inside whole cloth with no other cut spoke (a cut one edge long)
    // cannot be opened by moving triangles from either end: two springs would join the same two
    // particles. Such an edge is split at its middle first, whose particle then opens both halves.
    void splitLoneEdges() {
        const std::vector<Index> edges = chain_;
        for (const Index e : edges) {
            const Index a = c_.springs[e].a, b = c_.springs[e].b;
            if (opensAt(a, e) || opensAt(b, e)) continue;
            const Index m = split(e, 0.5); // e is now a-m
            record(m);
            const Index half = findSpring(c_, m, b);
            chain_.insert(std::lower_bound(chain_.begin(), chain_.end(), half), half);
        }
    }

    // ========================================================================================= [SEPARATE]
    // The triangle groups of v: each fan apart (a one-point connection on the stroke is cut), and
    // each fan divided at its cut spokes (a closed fan needs two to fall apart).
    std::vector<std::vector<Index>> groupsAt(Index v) const {
        std::vector<std::vector<Index>> groups;
        for (const Fan& f : fansAround(c_, v)) {
            const int k = int(f.tris.size());
            std::vector<int> cuts; // spokes[j] lies between tris[j-1] and tris[j] (closed: tris[k-1] and tris[0])
            for (int j = f.closed ? 0 : 1; j < k; ++j)
                if (isCutSpoke(f.spokes[size_t(j)])) cuts.push_back(j);
            if (!f.closed) {
                int start = 0;
                for (int j : cuts) groups.emplace_back(f.tris.begin() + start, f.tris.begin() + j), start = j;
                groups.emplace_back(f.tris.begin() + start, f.tris.end());
            } else if (cuts.size() < 2) {
                groups.push_back(f.tris);
            } else {
                for (size_t i = 0; i < cuts.size(); ++i) {
                    const int to = i + 1 < cuts.size() ? cuts[i + 1] : cuts[0] + k;
                    std::vector<Index>& g = groups.emplace_back();
                    for (int j = cuts[i]; j < to; ++j) g.push_back(f.tris[size_t(j % k)]);
                }
            }
        }
        return groups;
    }

    void separateAt(Index v, const TearContext& ctx) {
        const std::vector<std::vector<Index>> groups = groupsAt(v);
        if (groups.size() < 2) return;
        std::vector<Index> touched(c_.particleTris[v].begin(), c_.particleTris[v].end());
        std::vector<Index> farEnds;
        for (size_t g = 1; g < groups.size(); ++g) {
            // The cut spokes this group still shares with triangles that stay on v: it takes copies.
            std::vector<Index> shared;
            for (Index t : groups[g]) {
                const Triangle& T = c_.triangles[t];
                const int corner = cornerOf(T, v);
                for (Index s : {T.s[corner], T.s[(corner + 2) % 3]}) {
                    const SpringTopo& topo = c_.springTopo[s];
                    if (topo.tri[1] == kNone) continue;
                    const Index other = topo.tri[0] == t ? topo.tri[1] : topo.tri[0];
                    if (std::find(groups[g].begin(), groups[g].end(), other) != groups[g].end()) continue;
                    if (std::find(shared.begin(), shared.end(), s) == shared.end()) shared.push_back(s);
                    farEnds.push_back(otherEnd(c_.springs[s], v));
                }
            }
            const Index q = detachGroup(c_, v, groups[g], shared, touched);
            if (ctx.copies) ctx.copies->emplace_back(v, q);
        }
        // As a weak-point tear: the far ends' fans changed too (their flags follow them).
        for (Index w : farEnds) touched.insert(touched.end(), c_.particleTris[w].begin(), c_.particleTris[w].end());
        std::sort(touched.begin(), touched.end());
        touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
        refreshAround(c_, touched);
        sync();
    }

    // One event per chain edge now open (each has one triangle left on either wall).
    void logCutSprings(const TearContext& ctx) {
        for (Index s : chain_) {
            const SpringTopo& topo = c_.springTopo[s];
            if (topo.tri[1] != kNone) continue; // still joined: cannot happen (validate and the tests say)
            out_.springsCut++;
            if (!ctx.log) continue;
            const Spring& sp = c_.springs[s];
            const Triangle& T = c_.triangles[topo.tri[0]];
            const int slot = edgeSlotOf(T, s);
            const Vec2d uv = 0.5 * (T.uv[slot] + T.uv[(slot + 1) % 3]);
            const float strain = (c_.x[sp.b] - c_.x[sp.a]).norm() / sp.rest - 1.f;
            ctx.log->add(TearEvent{TearMode::Knife, ctx.time, 0.5 * (c_.rest[sp.a] + c_.rest[sp.b]), uv, strain, sp.rest, sp.weight});
        }
    }

    Cloth& c_;
    const MeshFrame& frame_;
    std::vector<Vec2d>& at_; // every particle's rest position in the frame
    CutResult& out_;
    const Vec2d a_, b_, d_;
    std::vector<Index> onStroke_; // particles the cut passes through
    std::vector<Index> chain_;    // sorted: the joined springs along the segment (the "cut spokes")
};

} // namespace

// =============================================================================================== [DRIVER]

MeshFrame knifeFrame(const std::vector<Vec3d>& meshPoints) {
    MeshFrame f = meshFrame(meshPoints);
    const double cu = 0.5 * (f.minU + f.maxU), cv = 0.5 * (f.minV + f.maxV);
    f.centre = f.at(cu, cv);
    f.minU -= cu, f.maxU -= cu, f.minV -= cv, f.maxV -= cv;
    return f;
}

std::string checkStroke(const std::vector<Vec2d>& stroke) {
    if (stroke.size() < 2) return "a cut needs at least two points (got " + std::to_string(stroke.size()) + ")";
    double length = 0;
    for (size_t i = 0; i < stroke.size(); ++i) {
        const std::string which = "point " + std::to_string(i + 1) + " of the cut";
        if (!stroke[i].allFinite()) return which + " is not a finite number";
        if (stroke[i].cwiseAbs().maxCoeff() > kMaxCoordinate) return which + " is beyond +-1e5 m (mesh.h kMaxCoordinate)";
        if (i) length += (stroke[i] - stroke[i - 1]).norm();
    }
    if (!(length > 0)) return "the cut has no length (all its points are the same)";
    return {};
}

CutResult cutAlong(Cloth& c, const MeshFrame& frame, const std::vector<Vec2d>& stroke, const TearContext& ctx) {
    CutResult out;
    out.error = checkStroke(stroke);
    if (!out.ok()) return out;
    const size_t before = c.particleCount();
    std::vector<Vec2d> at;
    at.reserve(before);
    for (const Vec3d& r : c.rest) at.push_back(Vec2d(frame.u(r), frame.v(r)));
    for (size_t i = 1; i < stroke.size(); ++i)
        if (stroke[i] != stroke[i - 1]) SegmentCut(c, frame, at, out, stroke[i - 1], stroke[i]).run(ctx);
    out.particlesAdded = c.particleCount() - before;
    if (out.springsCut > 0 && ctx.log) ctx.log->knifeCuts++;
    return out;
}

} // namespace clothtear
