// Tool actions on the world.
#include "tools.h"

#include "picking.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace clothtear::app {

const char* toolName(Tool tool) {
    static const char* names[] = {"Drag", "Wind", "Impulse", "Ball", "Pin", "Knife"};
    return names[int(tool)];
}

View makeView(const OrbitCamera& camera, float width, float height) {
    View v;
    v.camera = camera;
    v.width = std::max(width, 1.f);
    v.height = std::max(height, 1.f);
    v.viewProjection = camera.viewProjection(v.width / v.height);
    return v;
}

// ============================================================================================ drag

bool beginDrag(World& world, DragState& drag, const View& view, const Vec2& cursor, float grabRadius) {
    const TriangleHit hit = pickTriangle(world.cloth, view.rayAt(cursor));
    const Index p = nearestCorner(world.cloth, hit);
    if (p == kNone) return false;
    drag.particle = p;
    drag.wasPinned = world.cloth.pinned(p);
    drag.planePoint = hit.point;
    drag.planeNormal = -view.camera.forward();
    drag.grabOffset = world.cloth.x[p] - hit.point;
    drag.target = world.cloth.x[p];
    drag.patch.clear();
    if (grabRadius > 0.f) {
        // The patch: particles joined to p through triangles, within grabRadius of it in rest space
        // (material distance). A folded layer behind, a torn-off piece or the far side of a tear
        // next to the hand share rest positions with the patch but not its material: not held.
        const Cloth& c = world.cloth;
        const Vec3d& r0 = c.rest[p];
        const double R2 = double(grabRadius) * grabRadius;
        std::vector<uint8_t> seen(c.particleCount(), 0);
        std::vector<Index> front{p};
        seen[p] = 1;
        while (!front.empty()) {
            const Index q = front.back();
            front.pop_back();
            for (Index t : c.particleTris[q])
                for (Index r : c.triangles[t].p) {
                    if (seen[r] || (c.rest[r] - r0).squaredNorm() > R2) continue;
                    seen[r] = 1;
                    front.push_back(r);
                    if ((c.x[r] - c.x[p]).norm() <= 2.f * grabRadius)
                        drag.patch.push_back({r, c.pinned(r), c.x[r] - c.x[p]});
                }
        }
        std::sort(drag.patch.begin(), drag.patch.end(),
                  [](const DragState::Held& a, const DragState::Held& b) { return a.particle < b.particle; });
    }
    // Held by the tool: forces no longer move them, the driver does.
    world.cloth.setPinned(p, true);
    for (const DragState::Held& h : drag.patch) world.cloth.setPinned(h.particle, true);
    return true;
}

void moveDrag(DragState& drag, const View& view, const Vec2& cursor) {
    if (!drag.active()) return;
    Vec3 onPlane;
    if (rayPlane(view.rayAt(cursor), drag.planePoint, drag.planeNormal, onPlane)) drag.target = onPlane + drag.grabOffset;
}

void releaseDrag(World& world, DragState& drag, bool keepPinned) {
    if (!drag.active()) return;
    const size_t n = world.cloth.particleCount();
    if (drag.particle < n) world.cloth.setPinned(drag.particle, keepPinned || drag.wasPinned);
    for (const DragState::Held& h : drag.patch)
        if (h.particle < n) world.cloth.setPinned(h.particle, keepPinned || h.wasPinned);
    drag = DragState{};
}

size_t dragBeforeStep(World& world, const DragState& drag, float maxSpeed) {
    if (!drag.active() || drag.particle >= world.cloth.particleCount()) return 0;
    const size_t before = world.drivers.size();
    const Cloth& c = world.cloth;
    const float dt = world.settings.time.frameDt;
    auto velocityTo = [&](const Vec3& target, const Vec3& x) {
        // A particle already where it should be holds still. The sub-steps' moves land on the target
        // only to round-off (about 1e-6 m at 2 m: 5e-5 m/s when divided by the frame), and a
        // velocity of that round-off kept the step in its "a hand moves" mode (the guard's
        // per-spring caps, the limit's pass cap, no overshoot rule) all the while the user held the
        // cloth still. Still means within 64 float ulps of the target's magnitude.
        const float still = 64.f * std::numeric_limits<float>::epsilon() * std::max(1.f, target.norm());
        if ((target - x).squaredNorm() <= still * still) return Vec3(Vec3::Zero());
        Vec3 v = (target - x) / dt;
        const float speed = v.norm();
        if (speed > maxSpeed) v *= maxSpeed / speed;
        return v;
    };
    // The hand stays above the ground: a cursor dragged below the horizon puts the drag plane's
    // point under the floor, and the held patch pulled through it while the ground pushed the cloth
    // around it back up stretched the springs between them to 90 x their rest length (a yank off the
    // bottom of the screen at 80 a side) and ran the limit's passes to their cap in every sub-step.
    const CollisionSettings& floor = world.settings.collision;
    auto onOrAbove = [&](Vec3 target) {
        if (floor.ground) target.y() = std::max(target.y(), floor.groundHeight + floor.thickness);
        return target;
    };
    // One driver per particle: each heads for its place in the rigid patch around the target.
    Driver d;
    d.particles = {drag.particle};
    d.velocity = velocityTo(onOrAbove(drag.target), c.x[drag.particle]);
    world.drivers.push_back(std::move(d));
    for (const DragState::Held& h : drag.patch) {
        if (h.particle >= c.particleCount()) continue;
        Driver e;
        e.particles = {h.particle};
        e.velocity = velocityTo(onOrAbove(drag.target + h.offset), c.x[h.particle]);
        world.drivers.push_back(std::move(e));
    }
    return world.drivers.size() - before;
}

void dragAfterStep(World& world, const DragState& drag, size_t pushed, size_t particlesBefore) {
    world.drivers.resize(world.drivers.size() - std::min(pushed, world.drivers.size()));
    Cloth& c = world.cloth;
    if (!drag.active() || c.particleCount() <= particlesBefore) return;
    auto restore = [&](Index held, bool wasPinned) {
        if (wasPinned || held >= c.rest.size()) return;
        for (Index q = Index(particlesBefore); q < c.particleCount(); ++q)
            if (c.pinned(q) && c.rest[q] == c.rest[held]) c.setPinned(q, false);
    };
    restore(drag.particle, drag.wasPinned);
    for (const DragState::Held& h : drag.patch) restore(h.particle, h.wasPinned);
}

// ==================================================================================== wind, impulse

void addVelocity(World& world, Index p, const Vec3& dv) {
    world.wake(); // a sleeping cloth (src/core/sleep.cpp) must feel the push
    world.cloth.v[p] += dv; // every integrator, Verlet too, keeps its velocity in v
}

WindSource windSourceAt(const View& view, const Vec2& cursor) {
    WindSource s;
    s.view = view;
    s.center = cursor;
    s.direction = view.rayAt(cursor).dir;
    return s;
}

int applyWind(World& world, const WindSource& source, float radiusPx, float pressure, float seconds) {
    Cloth& c = world.cloth;
    const auto hits = particlesInScreenRadius(c, source.view.viewProjection, source.view.width, source.view.height,
                                              source.center, radiusPx);
    for (const WeightedParticle& h : hits) {
        if (c.asleep(h.particle)) world.wake(); // a sleeping torn piece: its inverse mass comes back
        if (c.invMass[h.particle] == 0.f) continue;
        // a = F / m = pressure * areaShare * invMass
        const float a = pressure * float(c.areaShare[h.particle]) * c.invMass[h.particle] * h.weight;
        addVelocity(world, h.particle, source.direction * (a * seconds));
    }
    return int(hits.size());
}

int applyScreenImpulse(World& world, const View& view, const Vec2& cursor, float radiusPx, float dv) {
    const Vec3 dir = view.rayAt(cursor).dir;
    const auto hits = particlesInScreenRadius(world.cloth, view.viewProjection, view.width, view.height, cursor, radiusPx);
    int n = 0;
    for (const WeightedParticle& h : hits) {
        if (world.cloth.asleep(h.particle)) world.wake(); // a sleeping torn piece: its inverse mass comes back
        if (world.cloth.invMass[h.particle] == 0.f) continue;
        addVelocity(world, h.particle, dir * (dv * h.weight));
        ++n;
    }
    return n;
}

// ====================================================================================== ball, pin

bool ballisticVelocity(const Vec3& from, const Vec3& to, const Vec3& g, float speed, Vec3& velocity, float& minSpeed) {
    const Vec3 d = to - from;
    const double gg = g.squaredNorm(), dg = d.dot(g), dd = d.squaredNorm(), s2 = double(speed) * speed;
    minSpeed = float(std::sqrt(std::max(0.0, std::sqrt(gg * dd) - dg)));
    if (dd < 1e-12) return false;
    if (gg < 1e-12) {
        velocity = d.normalized() * speed;
        return speed > 0.f;
    }
    const double a = 0.25 * gg, b = -(dg + s2), c = dd;
    const double disc = b * b - 4.0 * a * c;
    if (disc < 0.0) return false;
    const double u = (-b - std::sqrt(disc)) / (2.0 * a); // the smaller t^2: the flatter arc
    if (!(u > 0.0)) return false;
    const float t = float(std::sqrt(u));
    velocity = d / t - 0.5f * g * t;
    return true;
}

Throw throwBall(const World& world, const View& view, const Vec2& cursor) {
    const SceneParams& params = world.settings.scene;
    const Ray r = view.rayAt(cursor);
    Throw out;
    Ball& b = out.ball;
    b.radius = params.ballRadius;
    b.mass = params.ballMass;
    // Start just in front of the eye so the ball does not appear inside the near plane.
    b.x = r.origin + r.dir * (b.radius + 0.2f);
    b.v = r.dir * params.ballSpeed;
    // The point under the cursor: the cloth, else the ground.
    Vec3 target;
    bool haveTarget = false;
    if (const TriangleHit hit = pickTriangle(world.cloth, r); hit.hit()) {
        target = hit.point;
        haveTarget = true;
    } else if (world.settings.collision.ground) {
        const float h = world.settings.collision.groundHeight + b.radius;
        haveTarget = rayPlane(r, Vec3(0.f, h, 0.f), Vec3::UnitY(), target);
    }
    if (haveTarget) {
        const Vec3 g(world.settings.gravity.x, world.settings.gravity.y, world.settings.gravity.z);
        Vec3 v;
        out.aimed = ballisticVelocity(b.x, target, g, params.ballSpeed, v, out.neededSpeed);
        if (out.aimed) b.v = v;
    }
    return out;
}

Index togglePinAt(World& world, const View& view, const Vec2& cursor) {
    const Index p = nearestCorner(world.cloth, pickTriangle(world.cloth, view.rayAt(cursor)));
    if (p == kNone) return kNone;
    world.cloth.setPinned(p, !world.cloth.pinned(p));
    if (world.cloth.pinned(p)) world.cloth.v[p].setZero();
    return p;
}

// ========================================================================================= knife

bool restPointUnder(const World& world, const View& view, const Vec2& cursor, Vec2d& point) {
    const TriangleHit hit = pickTriangle(world.cloth, view.rayAt(cursor));
    if (!hit.hit()) return false;
    const Triangle& t = world.cloth.triangles[hit.triangle];
    const double b1 = hit.b1, b2 = hit.b2;
    const Vec3d rest = (1.0 - b1 - b2) * world.cloth.rest[t.p[0]] + b1 * world.cloth.rest[t.p[1]] + b2 * world.cloth.rest[t.p[2]];
    point = Vec2d(world.restFrame.u(rest), world.restFrame.v(rest));
    return true;
}

void knifeBegin(const World& world, KnifeState& knife, const View& view, const Vec2& cursor) {
    knife = KnifeState{};
    knife.held = true;
    knife.trail.push_back(cursor);
    knife.onCloth = restPointUnder(world, view, cursor, knife.last);
    knife.fromOutside = !knife.onCloth;
}

size_t knifeMove(World& world, KnifeState& knife, const View& view, const Vec2& cursor) {
    if (!knife.held) return 0;
    if ((knife.trail.back() - cursor).norm() >= 1.f) knife.trail.push_back(cursor);
    const MeshFrame& f = world.restFrame;
    const double reach = f.width() + f.height(); // from any point of the cloth past its edge
    Vec2d p;
    const bool hit = restPointUnder(world, view, cursor, p);
    std::vector<Vec2d> stroke;
    if (hit && !knife.onCloth) { // onto the cloth: the direction comes with the next point
        knife.last = p, knife.onCloth = true, knife.fromOutside = true, knife.direction.setZero();
        return 0;
    }
    if (!hit) { // off the cloth (or still off): carry the stroke on to the edge once
        if (knife.onCloth && knife.direction.squaredNorm() > 0) stroke = {knife.last, knife.last + reach * knife.direction};
        knife.onCloth = false;
    } else {
        const Vec2d step = p - knife.last;
        if (step.norm() <= 1e-6 * reach) return 0; // not moved on the material (snapping would make it nothing)
        knife.direction = step.normalized();
        stroke = {knife.fromOutside ? Vec2d(knife.last - reach * knife.direction) : knife.last, p};
        knife.fromOutside = false;
        knife.last = p;
    }
    if (stroke.empty()) return 0;
    const size_t cut = world.cut(stroke).springsCut;
    knife.springsCut += cut;
    return cut;
}

void knifeEnd(KnifeState& knife) {
    knife.held = false;
    knife.trail.clear();
}

} // namespace clothtear::app
