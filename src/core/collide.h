// Cloth against balls (two-way, swept) and the ground plane. Internal to the core.
#pragma once
#include "clothtear/cloth.h"
#include "clothtear/settings.h"
#include "clothtear/world.h"

#include <vector>

namespace clothtear {

// Moves the balls one sub-step (gravity, ground bounce) and resolves their contacts with the cloth
// triangles, then keeps cloth particles above the ground.
void collideBallsAndGround(Cloth& cloth, std::vector<Ball>& balls, const CollisionSettings& settings,
                           const Vec3& gravity, float dt);

// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection 5.1.5), with barycentric
// weights of the result.
Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, Vec3& bary);

} // namespace clothtear
