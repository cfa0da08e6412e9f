// Cloth against balls and the ground.
//
// Balls are resolved against triangles, not only particles: the closest point of each nearby
// triangle to the ball centre is pushed out to the ball surface, with the correction and the impulse
// split over the corners by barycentric weight. A ball whose centre crossed a triangle during the
// sub-step (a fast ball) is caught by a segment-triangle test and the cloth is put back in front of
// it, so nothing tunnels. Momentum is exchanged both ways: the ball slows down when it hits cloth.
#include "collide.h"

#include "parallel.h"

#include <algorithm>
#include <cmath>

namespace clothtear {

Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, Vec3& bary) {
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

namespace {

// Does segment p0->p1 pass through triangle abc (its interior or boundary)?
bool segmentCrossesTriangle(const Vec3& p0, const Vec3& p1, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 n = (b - a).cross(c - a);
    const float s0 = n.dot(p0 - a), s1 = n.dot(p1 - a);
    if ((s0 > 0.f) == (s1 > 0.f) || s0 == s1) return false;
    const Vec3 hit = p0 + (p1 - p0) * (s0 / (s0 - s1));
    const float e0 = (b - a).cross(hit - a).dot(n), e1 = (c - b).cross(hit - b).dot(n), e2 = (a - c).cross(hit - c).dot(n);
    return (e0 >= 0.f && e1 >= 0.f && e2 >= 0.f) || (e0 <= 0.f && e1 <= 0.f && e2 <= 0.f);
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

// One contact between a ball and the point q = sum b_i x_i of a triangle; n points from the ball
// centre to where the cloth must be, pen is how far q must move along n.
void resolveContact(Cloth& cloth, const Triangle& tri, const Vec3& bary, Ball& ball, const Vec3& n, float pen,
                    float friction, float dt) {
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
        cloth.xPrev[p] += dx - dv * dt; // Verlet: the push is not a velocity, the impulse is
    }
}

void collideBall(Cloth& cloth, Ball& ball, const Vec3& c0, const CollisionSettings& s, float dt) {
    const float R = ball.radius + s.thickness;
    const Vec3 lo = c0.cwiseMin(ball.x).array() - R, hi = c0.cwiseMax(ball.x).array() + R;
    // Pass 0 resolves only the triangles the ball went through, so that it is back on its side
    // before pass 1 judges the contacts with their neighbours from the ball centre (a centre lying
    // in the cloth would otherwise be shoved sideways by them, past the triangle it crossed).
    for (int pass = 0; pass < 2; ++pass) {
        for (const Triangle& tri : cloth.triangles) {
            // Where the ball is now: a pinned triangle met earlier may have pushed it back, and a
            // stale end point would push it back once more for every triangle it crossed.
            const Vec3 c1 = ball.x;
            const Vec3& a = cloth.x[tri.p[0]];
            const Vec3& b = cloth.x[tri.p[1]];
            const Vec3& c = cloth.x[tri.p[2]];
            // Broad phase: triangle box against the swept ball box.
            const Vec3 tlo = a.cwiseMin(b).cwiseMin(c), thi = a.cwiseMax(b).cwiseMax(c);
            if ((tlo.array() > hi.array()).any() || (thi.array() < lo.array()).any()) continue;
            Vec3 bary;
            const Vec3 q = closestPointOnTriangle(c1, a, b, c, bary);
            Vec3 nt = (b - a).cross(c - a);
            const float ntLen = nt.norm();
            if (!(ntLen > 0.f)) continue;
            nt /= ntLen;
            const float side0 = nt.dot(c0 - a) >= 0.f ? 1.f : -1.f;
            Vec3 n;
            float pen;
            const bool crossed = segmentCrossesTriangle(c0, c1, a, b, c);
            if (pass == 0 && !crossed) continue;
            if (crossed) {
                // Tunnelled this sub-step: the cloth belongs in front of the ball.
                n = -side0 * nt;
                pen = R - (q - c1).dot(n);
            } else {
                const Vec3 d = q - c1;
                const float dist = d.norm();
                if (dist >= R) continue;
                n = dist > 1e-6f * R ? Vec3(d / dist) : Vec3(-side0 * nt);
                pen = R - dist;
            }
            if (pen > 0.f) resolveContact(cloth, tri, bary, ball, n, pen, s.friction, dt);
        }
    }
}

void collideGround(Cloth& cloth, const CollisionSettings& s, float dt) {
    const float floorY = s.groundHeight + s.thickness;
    const size_t n = cloth.particleCount();
    parallelRegion(n, n >= 2048 ? maxThreads() : 1, [&](int t, int nt) {
        const Chunk c = chunkOf(n, t, nt);
        for (size_t p = c.begin; p < c.end; ++p) {
            Vec3& x = cloth.x[p];
            if (x.y() >= floorY || cloth.invMass[p] == 0.f) continue;
            Vec3& v = cloth.v[p];
            const float dy = floorY - x.y();
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
            cloth.xPrev[p] += Vec3(0.f, dy, 0.f) - dv * dt;
        }
    });
}

} // namespace

void collideBallsAndGround(Cloth& cloth, std::vector<Ball>& balls, const CollisionSettings& s, const Vec3& gravity,
                           float dt) {
    for (Ball& ball : balls) {
        const Vec3 c0 = ball.x;
        integrateBall(ball, s, gravity, dt);
        collideBall(cloth, ball, c0, s, dt);
    }
    if (s.ground) collideGround(cloth, s, dt);
}

} // namespace clothtear
