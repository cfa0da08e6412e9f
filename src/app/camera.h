// Orbit camera math: view/projection matrices, rays through window pixels, projection to the window.
// Pure math (Eigen only, no GL), so picking and tool tests run without a window.
#pragma once
#include "clothtear/types.h"
#include "clothtear/world.h"

#include <Eigen/Core>

namespace clothtear::app {

using Mat4 = Eigen::Matrix4f; // column-major, as glUniformMatrix4fv expects
using Vec2 = Eigen::Vector2f;

struct Ray {
    Vec3 origin = Vec3::Zero();
    Vec3 dir = Vec3(0, 0, -1); // unit length
};

// Looks at `target` from `distance` away; yaw turns about +y (0 = looking from +z towards -z),
// pitch raises the eye above the target.
struct OrbitCamera {
    Vec3 target = Vec3(0.f, -0.4f, 0.f); // m
    float yaw = 0.35f;                   // rad
    float pitch = 0.18f;                 // rad, clamped to (-1.5, 1.5)
    float distance = 5.5f;               // m, [0.1, 500]
    float fovY = 0.8f;                   // rad, vertical field of view
    float nearZ = 0.02f;                 // m
    float farZ = 500.f;                  // m
    float shiftX = 0.f;                  // NDC units the image centre moves right, so what the camera
                                         // looks at stays centred in the part of the window the panel
                                         // leaves free (a lens shift: rays and projection both use it)

    Vec3 position() const;
    Vec3 forward() const; // unit, from the eye towards the target
    Vec3 right() const;   // unit, horizontal
    Vec3 up() const;      // unit, completes the frame

    Mat4 view() const;
    Mat4 projection(float aspect) const;
    Mat4 viewProjection(float aspect) const { return projection(aspect) * view(); }

    // Right-drag orbit: pixels of mouse motion to angles.
    void orbit(float dxPixels, float dyPixels);
    // Wheel zoom: each step scales the distance by 0.9 (in) or 1/0.9 (out).
    void zoom(float wheelSteps);
    // Middle-drag pan: moves the target in the view plane, scaled so the grabbed point follows the cursor.
    void pan(float dxPixels, float dyPixels, float windowHeight);
    // Fly keys: moves the target along the camera frame (x = right, y = world up, z = forward).
    void fly(const Vec3& local, float seconds);
    // Frames an axis-aligned box: target at its centre, distance so that it fills most of the view.
    void frame(const Vec3& boxMin, const Vec3& boxMax);
};

// Frames the cloth and its torn pieces, and the balls among them (the drop scene's ball on the
// ground): everything within 0.75 rest diagonals of the cloth's median point. What has flown or fallen
// further (a ball gone through, a piece falling without ground) is left out, so V never zooms out to
// a speck.
void frameWorld(OrbitCamera& camera, const World& world);

// The ray from the eye through window point (px, py) (origin top-left, pixels) of a width x height window.
Ray rayThroughPixel(const OrbitCamera& camera, float px, float py, float width, float height);

// Window coordinates (origin top-left) of world point p; false when it lies behind the eye.
bool projectToWindow(const Mat4& viewProjection, const Vec3& p, float width, float height, Vec2& out);

// Intersection of a ray with the plane through `point` with normal `normal`; false when parallel
// or behind the origin.
bool rayPlane(const Ray& ray, const Vec3& point, const Vec3& normal, Vec3& hit);

} // namespace clothtear::app
