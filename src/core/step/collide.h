// Cloth against balls (two-way, swept) and the ground plane. Internal to the core.
#pragma once
#include "clothtear/cloth.h"
#include "clothtear/settings.h"
#include "step_state.h"

#include <vector>

namespace clothtear {

// Collide phase (before the limit): moves the balls one sub-step (gravity, ground bounce) and pushes
// the cloth out of them, two-way; lists each ball-triangle contact with the side the ball belongs
// on in `contacts`. Moved particles are written to `packed` as well (the limit reads it).
// `maxEdge` bounds every triangle edge this sub-step (the ball broad phase, see trianglesIn; infinite:
// no bound, every triangle is tested).
void collideBalls(Cloth& cloth, std::vector<Ball>& balls, const CollisionSettings& settings, const Vec3& gravity,
                  float dt, float maxEdge, PackedParticle* packed, std::vector<BallContact>& contacts);

// Contact phase (after the limit): if the limit held the cloth (`clothHeld`), balls pressing into
// the cloth that held them give way and other cloth in a ball is pushed out, keeping the sides
// listed in `contacts`; then cloth particles are kept above the ground. `contactOf` is scratch (per
// triangle, all -1 between calls).
void settleContacts(Cloth& cloth, std::vector<Ball>& balls, const CollisionSettings& settings, float dt, float maxEdge,
                    bool clothHeld, const std::vector<BallContact>& contacts, std::vector<int32_t>& contactOf);

// One ball, one sub-step, with nothing but gravity and the ground (a little bounce, friction): what
// the collide phase does to a ball before it meets the cloth.
void integrateBall(Ball& ball, const CollisionSettings& settings, const Vec3& gravity, float dt);

// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection 5.1.5), with barycentric
// weights of the result.
Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, Vec3& bary);

} // namespace clothtear
