// Cloth against balls and the ground, in two phases around the length limit.
//
// Collide (before the limit): balls move, and are resolved against triangles, not only particles:
// the closest point of each nearby triangle to the ball centre is pushed out to the ball surface,
// with the correction and the impulse split over the corners by barycentric weight, so momentum is
// exchanged both ways. Which side of a triangle a ball belongs on is judged from where both started
// the sub-step, so a fast ball that went through a triangle, or a triangle that went through the
// ball, is caught and the cloth put back in front of the ball: nothing tunnels.
// Contact (after the limit): the limit pulls the struck cloth back towards its anchors, into the
// ball; there the ball gives way, keeping the sides found before. A heavy fast ball is stopped by
// the taut cloth as by a net, instead of dragging the cloth along until it slips through.
#include "collide.h"

#include "parallel.h"

#include <algorithm>
#include <cmath>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace clothtear {

namespace {

// Ericson, Real-Time Collision Detection 5.1.5. A degenerate triangle (a torn sliver squashed flat,
// two corners on one point) divides 0 by 0 in it: closestPointOnTriangle checks.
Vec3 closestPointOnTriangleUnchecked(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, Vec3& bary) {
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const float d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0.f && d2 <= 0.f) return bary = Vec3(1, 0, 0), a;
    const Vec3 bp = p - b;
    const float d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0.f && d4 <= d3) return bary = Vec3(0, 1, 0), b;
    const float vc = d1 * d4 - d3 * d2;
    if (vc <= 0.f && d1 >= 0.f && d3 <= 0.f) {
        const float v = d1 / (d1 - d3);
        return bary = Vec3(1 - v, v, 0), a + v * ab;
    }
    const Vec3 cp = p - c;
    const float d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0.f && d5 <= d6) return bary = Vec3(0, 0, 1), c;
    const float vb = d5 * d2 - d1 * d6;
    if (vb <= 0.f && d2 >= 0.f && d6 <= 0.f) {
        const float w = d2 / (d2 - d6);
        return bary = Vec3(1 - w, 0, w), a + w * ac;
    }
    const float va = d3 * d6 - d5 * d4;
    if (va <= 0.f && (d4 - d3) >= 0.f && (d5 - d6) >= 0.f) {
        const float w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return bary = Vec3(0, 1 - w, w), b + w * (c - b);
    }
    const float denom = 1.f / (va + vb + vc);
    const float v = vb * denom, w = vc * denom;
    bary = Vec3(1 - v - w, v, w);
    return a + ab * v + ac * w;
}

} // namespace

Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, Vec3& bary) {
    const Vec3 q = closestPointOnTriangleUnchecked(p, a, b, c, bary);
    if (bary.allFinite()) return q;
    // Degenerate: the nearest corner (found by the random safe-parameter runs: a NaN position after
    // the collide phase when an 83 kg ball hit a torn forward-Euler cloth).
    const float da = (p - a).squaredNorm(), db = (p - b).squaredNorm(), dc = (p - c).squaredNorm();
    if (da <= db && da <= dc) return bary = Vec3(1, 0, 0), a;
    if (db <= dc) return bary = Vec3(0, 1, 0), b;
    return bary = Vec3(0, 0, 1), c;
}

void integrateBall(Ball& ball, const CollisionSettings& s, const Vec3& gravity, float dt) {
    ball.v += gravity * dt;
    ball.x += ball.v * dt;
    if (s.ground && ball.x.y() - ball.radius < s.groundHeight) {
        ball.x.y() = s.groundHeight + ball.radius;
        if (ball.v.y() < 0.f) {
            const float vn = -ball.v.y();
            ball.v.y() = 0.3f * vn; // a little bounce
            Vec3 vt(ball.v.x(), 0.f, ball.v.z());
            const float vtLen = vt.norm();
            if (vtLen > 0.f) {
                const float drop = std::min(vtLen, s.friction * 1.3f * vn);
                ball.v.x() -= vt.x() / vtLen * drop;
                ball.v.z() -= vt.z() / vtLen * drop;
            }
        }
    }
}

namespace {

// One contact between a ball and the point q = sum b_i x_i of a triangle; n points from the ball
// centre to where the cloth must be, pen is how far q must move along n.
void resolveContact(Cloth& cloth, const Triangle& tri, const Vec3& bary, Ball& ball, const Vec3& n, float pen,
                    float friction) {
    float w[3], wsum = 0.f;
    for (int i = 0; i < 3; ++i) {
        w[i] = cloth.invMass[tri.p[i]] * bary[i];
        wsum += w[i] * bary[i];
    }
    const float invMb = ball.mass > 0.f ? 1.f / ball.mass : 0.f;
    if (wsum == 0.f) {
        // Pinned triangle: the ball alone gives way.
        ball.x -= n * pen;
        const float vn = ball.v.dot(n);
        if (vn > 0.f) ball.v -= vn * n;
        return;
    }
    Vec3 vq = Vec3::Zero();
    for (int i = 0; i < 3; ++i) vq += bary[i] * cloth.v[tri.p[i]];
    const Vec3 vrel = vq - ball.v;
    const float vn = vrel.dot(n);
    Vec3 impulse = Vec3::Zero(); // on the cloth point
    if (vn < 0.f) {
        const float K = wsum + invMb;
        const float j = -vn / K;
        impulse = j * n;
        const Vec3 vt = vrel - vn * n;
        const float vtLen = vt.norm();
        if (vtLen > 1e-9f) impulse -= (std::min(friction * j, vtLen / K) / vtLen) * vt;
    }
    ball.v -= impulse * invMb;
    for (int i = 0; i < 3; ++i) {
        if (w[i] == 0.f) continue;
        const Index p = tri.p[i];
        const Vec3 dx = n * (pen * w[i] / wsum);
        const Vec3 dv = impulse * w[i];
        cloth.x[p] += dx;
        cloth.v[p] += dv;
    }
}

// Contact passes of the collide phase after the crossed triangles (they stop once one pushes
// nothing), and the penetration (fraction of the ball radius) left alone: a contact pushed out
// exactly sits at the radius, and round-off must not count as another push.
inline float sq(float a) { return a * a; }

constexpr int kContactPasses = 4;
constexpr float kContactSlop = 1e-4f;

// Where the corners of a triangle were at the start of the sub-step. Right after the integrator
// x = x0 + v dt exactly (semi-implicit Euler, Verlet; forward Euler to O(dt^2)), and the collide
// phase runs right after it.
inline Vec3 startOf(const Cloth& cloth, Index p, float dt) { return cloth.x[p] - cloth.v[p] * dt; }

// Is point c over triangle abc (its projection along the normal n inside the triangle)?
inline bool over(const Vec3& c, const Vec3& a, const Vec3& b, const Vec3& cc, const Vec3& n) {
    const float e0 = (b - a).cross(c - a).dot(n), e1 = (cc - b).cross(c - b).dot(n), e2 = (a - cc).cross(c - cc).dot(n);
    return (e0 >= 0.f && e1 >= 0.f && e2 >= 0.f) || (e0 <= 0.f && e1 <= 0.f && e2 <= 0.f);
}

// How a ball touches one triangle: the direction n from the ball centre to where the cloth must be
// and how far the touching point must move along it.
struct Touch {
    Vec3 bary;
    Vec3 n;
    float pen = 0.f;
};

// The contact of a ball (centre c, reach R) with triangle abc (unit normal nt) when the ball belongs
// on side `side` of the triangle (+1: along nt). A centre on the wrong side, over the triangle, went
// through it (or the triangle went through the ball): the cloth belongs back in front of the ball.
// Otherwise the closest point is pushed out to the ball surface.
inline bool touch(const Vec3& c, float R, const Vec3& a, const Vec3& b, const Vec3& cc, const Vec3& nt, float side,
                  Touch& t) {
    const Vec3 q = closestPointOnTriangle(c, a, b, cc, t.bary);
    if (side * nt.dot(c - a) < 0.f && over(c, a, b, cc, nt)) {
        t.n = -side * nt;
        t.pen = R - (q - c).dot(t.n);
        return t.pen > 0.f;
    }
    const Vec3 d = q - c;
    const float dist2 = d.squaredNorm();
    if (dist2 >= R * R) return false;
    const float dist = std::sqrt(dist2);
    t.n = dist > 1e-6f * R ? Vec3(d / dist) : Vec3(-side * nt);
    t.pen = R - dist;
    return true;
}

inline bool boxesOverlap(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& lo, const Vec3& hi) {
    const Vec3 tlo = a.cwiseMin(b).cwiseMin(c), thi = a.cwiseMax(b).cwiseMax(c);
    return !((tlo.array() > hi.array()).any() || (thi.array() < lo.array()).any());
}

// The triangles near one ball for one phase (trianglesIn, ascending), with what the passes know of
// each. The passes repeat over the same list, and what decides a triangle's contact is its corners'
// positions and velocities and the ball's centre; so a triangle none of whose corners moved since
// it was last looked at (`touched` marks the triangles of a corner that moved) gives the same
// answer again: whether its box overlaps the ball's box (`box`), and, for the contact passes after
// the first, that it pushes nothing (`quiet`). The passes skip those and do exactly what they did
// when they looked at every triangle each time, a few times faster under a ball in the cloth (most
// of the list lies outside the ball's box: the list covers the box grown by the radius).
struct NearTriangles {
    enum Box : uint8_t { kUnknown, kOutside, kOverlaps };
    std::vector<Index> tri;
    std::vector<uint8_t> box;   // Box, as of the corners' positions when tested
    std::vector<uint8_t> quiet; // looked at by a contact pass (1+) since anything it reads changed

    // Listed with the triangle: whether its box overlaps the ball's box (the corners are loaded then).
    void add(Index t, bool overlaps) {
        tri.push_back(t);
        box.push_back(overlaps ? kOverlaps : kOutside);
    }
    // Particle p moved: its triangles must be looked at again.
    void touched(const Cloth& cloth, Index p) {
        for (Index t : cloth.particleTris[p]) {
            const auto it = std::lower_bound(tri.begin(), tri.end(), t);
            if (it == tri.end() || *it != t) continue;
            const size_t k = size_t(it - tri.begin());
            box[k] = kUnknown;
            quiet[k] = 0;
        }
    }
    // The ball's centre moved: every contact answer may change (the boxes tested are fixed).
    void ballMoved() { std::fill(quiet.begin(), quiet.end(), uint8_t(0)); }
};

// The triangles whose box overlaps [lo, hi], once per ball and phase, in index order, each with
// whether its box overlaps the ball's own box [ballLo, ballHi] (inside [lo, hi]); the contact passes
// then look at these only. Broad phase: every point of a triangle lies within its longest
// edge of each of its corners, so a triangle overlapping the box has all its corners in the box
// grown by maxEdge (a bound on every edge this sub-step). One pass over the particle positions
// marks those (`inside`, scratch); each triangle is then listed once, from its lowest marked
// corner. Where more than an eighth of the cloth is marked, or without a bound (maxEdge infinite:
// no limit and no tearing), every triangle's box is tested instead, which is then cheaper.
NearTriangles trianglesIn(const Cloth& cloth, const Vec3& lo, const Vec3& hi, const Vec3& ballLo, const Vec3& ballHi,
                          float maxEdge, std::vector<uint8_t>& inside) {
    NearTriangles near;
    const size_t n = cloth.particleCount();
    size_t marked = n;
    if (std::isfinite(maxEdge)) {
        const Eigen::Array3f glo = lo.array() - maxEdge, ghi = hi.array() + maxEdge;
        inside.resize(n);
        marked = 0;
        for (Index p = 0; p < n; ++p) {
            const Eigen::Array3f x = cloth.x[p].array();
            inside[p] = !((x < glo).any() || (x > ghi).any());
            marked += inside[p];
        }
    }
    auto consider = [&](Index ti) {
        const Triangle& tri = cloth.triangles[ti];
        const Vec3 &a = cloth.x[tri.p[0]], &b = cloth.x[tri.p[1]], &c = cloth.x[tri.p[2]];
        if (boxesOverlap(a, b, c, lo, hi)) near.add(ti, boxesOverlap(a, b, c, ballLo, ballHi));
    };
    if (8 * marked > n) {
        for (Index ti = 0; ti < Index(cloth.triangles.size()); ++ti) consider(ti);
    } else {
        for (Index p = 0; p < n; ++p) {
            if (!inside[p]) continue;
            for (Index ti : cloth.particleTris[p]) {
                bool first = true;
                for (Index q : cloth.triangles[ti].p) first &= !(q < p && inside[q]);
                if (first) consider(ti);
            }
        }
        // The order of a full scan: results do not depend on the broad phase.
        std::vector<size_t> order(near.tri.size());
        for (size_t k = 0; k < order.size(); ++k) order[k] = k;
        std::sort(order.begin(), order.end(), [&](size_t i, size_t j) { return near.tri[i] < near.tri[j]; });
        NearTriangles sorted;
        for (size_t k : order) sorted.add(near.tri[k], near.box[k] == NearTriangles::kOverlaps);
        near = std::move(sorted);
    }
    near.quiet.assign(near.tri.size(), 0);
    return near;
}

// Visits the triangles of `near` whose box (now) overlaps [lo, hi] with their corners and unit normal.
// With `contactPass` (1, 2, ...: the contact passes after the first one, 0), the triangles it visits
// are marked quiet, and from the second contact pass on the quiet ones are not visited again.
template <class F>
void forTrianglesIn(const Cloth& cloth, NearTriangles& near, const Vec3& lo, const Vec3& hi, int contactPass, F&& f) {
    for (size_t k = 0; k < near.tri.size(); ++k) {
        if (near.box[k] == NearTriangles::kOutside || (contactPass >= 2 && near.quiet[k])) continue;
        const Index ti = near.tri[k];
        const Triangle& tri = cloth.triangles[ti];
        const Vec3& a = cloth.x[tri.p[0]];
        const Vec3& b = cloth.x[tri.p[1]];
        const Vec3& c = cloth.x[tri.p[2]];
        if (near.box[k] == NearTriangles::kUnknown) {
            near.box[k] = boxesOverlap(a, b, c, lo, hi) ? NearTriangles::kOverlaps : NearTriangles::kOutside;
            if (near.box[k] == NearTriangles::kOutside) continue;
        }
        if (contactPass >= 1) near.quiet[k] = 1; // a push below moves its corners and clears it
        Vec3 nt = (b - a).cross(c - a);
        const float len = nt.norm();
        if (!(len > 0.f)) continue;
        f(ti, tri, a, b, c, Vec3(nt / len));
    }
}

// resolveContact, and the near list told what moved.
void push(Cloth& cloth, NearTriangles& near, const Triangle& tri, const Vec3& bary, Ball& ball, const Vec3& n, float pen,
          float friction) {
    const Vec3 centre = ball.x;
    resolveContact(cloth, tri, bary, ball, n, pen, friction);
    for (Index p : tri.p) near.touched(cloth, p);
    if (ball.x != centre) near.ballMoved();
}

// Collide phase, one ball (moved from c0 to ball.x this sub-step). The side a ball belongs on is
// judged relative to the moving cloth: the ball's start c0 against where the triangle started, so a
// triangle that moved through the ball counts as crossed as much as a ball that moved through it.
void collideBall(Cloth& cloth, Ball& ball, uint32_t ballIndex, const Vec3& c0, const CollisionSettings& s, float dt,
                 float maxEdge, std::vector<uint8_t>& inside, PackedParticle* packed, std::vector<BallContact>& contacts) {
    const float R = ball.radius + s.thickness;
    const Vec3 lo = c0.cwiseMin(ball.x).array() - R, hi = c0.cwiseMax(ball.x).array() + R;
    // Pass 0 resolves only the triangles the ball is through, so that it is back on its side before
    // the later passes judge the contacts with their neighbours from the ball centre (a centre lying
    // in the cloth would otherwise be shoved sideways by them, past the triangle it crossed). Pushing
    // one triangle out moves its neighbours' shared corners, so the contact passes repeat until
    // nothing is left inside the ball: the contact phase must see only what the limit did.
    const size_t first = contacts.size();
    // Pushed triangles move away from the ball; a margin of R more covers those pushed into the box.
    NearTriangles near = trianglesIn(cloth, lo.array() - R, hi.array() + R, lo, hi, maxEdge, inside);
    for (int pass = 0; pass < 1 + kContactPasses; ++pass) {
        bool pushed = false;
        forTrianglesIn(cloth, near, lo, hi, pass, [&](Index ti, const Triangle& tri, const Vec3& a, const Vec3& b,
                                                     const Vec3& c, const Vec3& nt) {
            const Vec3 a0 = startOf(cloth, tri.p[0], dt);
            const Vec3 n0 = (startOf(cloth, tri.p[1], dt) - a0).cross(startOf(cloth, tri.p[2], dt) - a0);
            const float side = n0.dot(c0 - a0) >= 0.f ? 1.f : -1.f;
            const bool through = side * nt.dot(ball.x - a) < 0.f && over(ball.x, a, b, c, nt);
            if (through != (pass == 0)) return;
            Touch t;
            if (!touch(ball.x, R, a, b, c, nt, side, t) || t.pen <= kContactSlop * R) return;
            push(cloth, near, tri, t.bary, ball, t.n, t.pen, s.friction);
            for (Index p : tri.p) packed[p] = packedOf(cloth.x[p], cloth.v[p]);
            pushed = true;
            for (Index p : tri.p) cloth.flags[p] |= kTouched;
            for (size_t i = first; i < contacts.size(); ++i)
                if (contacts[i].triangle == ti) return;
            contacts.push_back(BallContact{ti, ballIndex, int8_t(side), {a, b, c}}); // corners refreshed below
        });
        if (pass > 0 && !pushed) break;
    }
    for (size_t i = first; i < contacts.size(); ++i)
        for (int k = 0; k < 3; ++k) contacts[i].at[k] = cloth.x[cloth.triangles[contacts[i].triangle].p[k]];
}

// Contact phase, one ball. The limit has put the cloth where its springs hold it. Where it pulled a
// triangle the ball pressed on back into the ball (its springs reached the strain the limit lets a
// ball stretch them to, see phaseLimit), the cloth holds and the ball gives way: it is moved out and
// loses its approach relative to the cloth, because pushing that cloth again would undo the limit
// and a heavy ball would drag the cloth along at any strain, and at last through itself. Any other
// triangle in the ball (moved in by the limit pulling on its neighbours) is pushed out two-way, as in
// the collide phase. The sides recorded by the collide phase hold: a triangle the limit snapped
// through the ball centre pushes the ball back. An immovable ball (mass 0) always pushes the cloth.
void settleBall(Cloth& cloth, Ball& ball, const CollisionSettings& s, float dt, float maxEdge, std::vector<uint8_t>& inside,
                const std::vector<BallContact>& contacts, const int32_t* contactOf) {
    const float R = ball.radius + s.thickness;
    const Vec3 lo = ball.x.array() - R, hi = ball.x.array() + R;
    const float moveTol2 = sq(1e-5f * R);
    NearTriangles near = trianglesIn(cloth, lo.array() - R, hi.array() + R, lo, hi, maxEdge, inside);
    for (int pass = 0; pass < 2; ++pass)
        forTrianglesIn(cloth, near, lo, hi, 0, [&](Index ti, const Triangle& tri, const Vec3& a, const Vec3& b,
                                                  const Vec3& c, const Vec3& nt) {
            const BallContact* contact = contactOf[ti] >= 0 ? &contacts[contactOf[ti]] : nullptr;
            const float now = nt.dot(ball.x - a) >= 0.f ? 1.f : -1.f;
            const float side = contact ? float(contact->side) : now;
            const bool through = side != now && over(ball.x, a, b, c, nt);
            if (through != (pass == 0)) return;
            Touch t;
            if (!touch(ball.x, R, a, b, c, nt, side, t) || t.pen <= kContactSlop * R) return;
            bool held = false;
            if (contact)
                for (int k = 0; k < 3; ++k) held |= (cloth.x[tri.p[k]] - contact->at[k]).squaredNorm() > moveTol2;
            if (!held || ball.mass <= 0.f) {
                push(cloth, near, tri, t.bary, ball, t.n, t.pen, s.friction);
                return;
            }
            // Moved back by pen, the ball loses pen / dt of its approach (position-based: the
            // velocity follows the correction), never more than its approach relative to the cloth.
            ball.x -= t.n * t.pen;
            Vec3 vq = Vec3::Zero();
            for (int i = 0; i < 3; ++i) vq += t.bary[i] * cloth.v[tri.p[i]];
            const float approach = (ball.v - vq).dot(t.n);
            if (approach > 0.f) ball.v -= std::min(approach, t.pen / dt) * t.n;
        });
    if (s.ground && ball.x.y() - ball.radius < s.groundHeight) ball.x.y() = s.groundHeight + ball.radius;
}

void collideGround(Cloth& cloth, const CollisionSettings& s) {
    const float floorY = s.groundHeight + s.thickness;
    const size_t n = cloth.particleCount();
    auto settle = [&](size_t p) {
        Vec3& x = cloth.x[p];
        if (x.y() >= floorY || cloth.invMass[p] == 0.f) return;
        Vec3& v = cloth.v[p];
        x.y() = floorY;
        Vec3 dv = Vec3::Zero();
        if (v.y() < 0.f) {
            const float vn = -v.y();
            dv.y() = vn;
            const Vec3 vt(v.x(), 0.f, v.z());
            const float vtLen = vt.norm();
            if (vtLen > 0.f) dv -= vt * (std::min(vtLen, s.friction * vn) / vtLen);
        }
        v += dv;
    };
    parallelRegion(n, n >= 2048 ? maxThreads() : 1, [&](int t, int nt) {
        const Chunk c = chunkOf(n, t, nt);
        size_t p = c.begin;
#if defined(__SSE2__)
        // Most sub-steps no particle is below the floor: four heights tested at once, from the
        // three 16-byte loads that hold four consecutive Vec3s (y at floats 1, 4, 7, 10), and the
        // particles looked at one by one only in a block where one may be (or is NaN, as before).
        const __m128 floor4 = _mm_set1_ps(floorY);
        const float* xs = cloth.x.data()->data();
        for (; p + 4 <= c.end; p += 4) {
            const float* f = xs + 3 * p;
            const __m128 a = _mm_loadu_ps(f), b = _mm_loadu_ps(f + 4), d = _mm_loadu_ps(f + 8);
            const __m128 lo = _mm_shuffle_ps(a, b, _MM_SHUFFLE(0, 0, 1, 1)); // y0 y0 y1 y1
            const __m128 hi = _mm_shuffle_ps(b, d, _MM_SHUFFLE(2, 2, 3, 3)); // y2 y2 y3 y3
            const __m128 y = _mm_shuffle_ps(lo, hi, _MM_SHUFFLE(2, 0, 2, 0)); // y0 y1 y2 y3
            if (_mm_movemask_ps(_mm_cmpnge_ps(y, floor4)) == 0) continue;
            for (size_t q = p; q < p + 4; ++q) settle(q);
        }
#endif
        for (; p < c.end; ++p) settle(p);
    });
}

} // namespace

void collideBalls(Cloth& cloth, std::vector<Ball>& balls, const CollisionSettings& s, const Vec3& gravity, float dt,
                  float maxEdge, PackedParticle* packed, std::vector<BallContact>& contacts) {
    contacts.clear();
    std::vector<uint8_t> inside; // broad-phase scratch, shared by the balls
    for (uint32_t i = 0; i < balls.size(); ++i) {
        Ball& ball = balls[i];
        if (ball.asleep) continue; // nothing within its reach moves (ball_sleep.cpp)
        const Vec3 c0 = ball.x;
        integrateBall(ball, s, gravity, dt);
        collideBall(cloth, ball, i, c0, s, dt, maxEdge, inside, packed, contacts);
    }
}

void settleContacts(Cloth& cloth, std::vector<Ball>& balls, const CollisionSettings& s, float dt, float maxEdge,
                    bool clothHeld, const std::vector<BallContact>& contacts, std::vector<int32_t>& contactOf) {
    contactOf.resize(cloth.triangles.size(), -1);
    std::vector<uint8_t> inside; // broad-phase scratch, shared by the balls
    for (const BallContact& c : contacts)
        for (Index p : cloth.triangles[c.triangle].p) cloth.flags[p] &= uint8_t(~kTouched);
    for (uint32_t i = 0; i < balls.size() && clothHeld; ++i) {
        if (balls[i].asleep) continue;
        for (size_t k = 0; k < contacts.size(); ++k)
            if (contacts[k].ball == i) contactOf[contacts[k].triangle] = int32_t(k);
        settleBall(cloth, balls[i], s, dt, maxEdge, inside, contacts, contactOf.data());
        for (const BallContact& c : contacts) contactOf[c.triangle] = -1;
    }
    if (s.ground) collideGround(cloth, s);
}

} // namespace clothtear
