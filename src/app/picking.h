// Picking against the current cloth: ray-triangle tests and screen-space particle selection.
// Pure (no GL): used by the tools and by the app tests.
#pragma once
#include "camera.h"
#include "clothtear/cloth.h"

#include <vector>

namespace clothtear::app {

struct TriangleHit {
    Index triangle = kNone; // kNone: nothing hit
    float t = 0.f;          // distance along the ray (m)
    float b1 = 0.f, b2 = 0.f; // barycentric weights of corners 1 and 2 (corner 0 gets 1 - b1 - b2)
    Vec3 point = Vec3::Zero();
    bool hit() const { return triangle != kNone; }
};

// Moller-Trumbore, two-sided (cloth has no inside). True on a hit in front of the origin.
bool rayTriangle(const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c, float& t, float& b1, float& b2);

// The closest triangle of the cloth along the ray.
TriangleHit pickTriangle(const Cloth& cloth, const Ray& ray);

// The corner particle of the hit triangle nearest to the hit point.
Index nearestCorner(const Cloth& cloth, const TriangleHit& hit);

// Particles whose window position lies within radiusPx of `center`, with a weight that falls from 1 at
// the centre to 0 at the rim (smooth, so tools do not make a visible step at the edge).
struct WeightedParticle {
    Index particle;
    float weight; // (0, 1]
};
std::vector<WeightedParticle> particlesInScreenRadius(const Cloth& cloth, const Mat4& viewProjection, float width,
                                                      float height, const Vec2& center, float radiusPx);

} // namespace clothtear::app
