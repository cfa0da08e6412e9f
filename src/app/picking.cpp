// Ray casting against the cloth and screen-space selection.
#include "picking.h"

#include <cmath>

namespace clothtear::app {

// Moller & Trumbore 1997: solve o + t d = (1 - b1 - b2) a + b1 b + b2 c with Cramer's rule.
bool rayTriangle(const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c, float& t, float& b1, float& b2) {
    const Vec3 e1 = b - a, e2 = c - a;
    const Vec3 p = ray.dir.cross(e2);
    const float det = e1.dot(p);
    if (std::abs(det) < 1e-12f) return false; // parallel or degenerate
    const float inv = 1.f / det;
    const Vec3 s = ray.origin - a;
    b1 = s.dot(p) * inv;
    if (b1 < 0.f || b1 > 1.f) return false;
    const Vec3 q = s.cross(e1);
    b2 = ray.dir.dot(q) * inv;
    if (b2 < 0.f || b1 + b2 > 1.f) return false;
    t = e2.dot(q) * inv;
    return t > 0.f;
}

TriangleHit pickTriangle(const Cloth& cloth, const Ray& ray) {
    TriangleHit best;
    best.t = 1e30f;
    for (Index i = 0; i < cloth.triangles.size(); ++i) {
        const Triangle& tri = cloth.triangles[i];
        float t, b1, b2;
        if (rayTriangle(ray, cloth.x[tri.p[0]], cloth.x[tri.p[1]], cloth.x[tri.p[2]], t, b1, b2) && t < best.t) {
            best.triangle = i;
            best.t = t;
            best.b1 = b1;
            best.b2 = b2;
        }
    }
    if (best.hit()) best.point = ray.origin + best.t * ray.dir;
    return best;
}

Index nearestCorner(const Cloth& cloth, const TriangleHit& hit) {
    if (!hit.hit()) return kNone;
    const Triangle& tri = cloth.triangles[hit.triangle];
    Index best = tri.p[0];
    float bestD = 1e30f;
    for (Index p : tri.p) {
        const float d = (cloth.x[p] - hit.point).squaredNorm();
        if (d < bestD) bestD = d, best = p;
    }
    return best;
}

std::vector<WeightedParticle> particlesInScreenRadius(const Cloth& cloth, const Mat4& vp, float width, float height,
                                                      const Vec2& center, float radiusPx) {
    std::vector<WeightedParticle> out;
    if (radiusPx <= 0.f) return out;
    const float r2 = radiusPx * radiusPx;
    for (Index p = 0; p < cloth.particleCount(); ++p) {
        Vec2 w;
        if (!projectToWindow(vp, cloth.x[p], width, height, w)) continue;
        const float d2 = (w - center).squaredNorm();
        if (d2 > r2) continue;
        // Smoothstep falloff: 1 - 3s^2 + 2s^3 with s = d / r.
        const float s = std::sqrt(d2) / radiusPx;
        out.push_back({p, std::max(1e-3f, 1.f - s * s * (3.f - 2.f * s))});
    }
    return out;
}

} // namespace clothtear::app
