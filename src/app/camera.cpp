// Orbit camera math. Conventions as in OpenGL: right-handed world, y up, clip z in [-1, 1].
#include "camera.h"

#include "clothtear/pieces.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace clothtear::app {

Vec3 OrbitCamera::forward() const {
    // Eye direction for yaw 0, pitch 0 is -z; positive pitch looks down from above.
    return Vec3(-std::sin(yaw) * std::cos(pitch), -std::sin(pitch), -std::cos(yaw) * std::cos(pitch));
}

Vec3 OrbitCamera::right() const { return Vec3(std::cos(yaw), 0.f, -std::sin(yaw)); }

Vec3 OrbitCamera::up() const { return right().cross(forward()).normalized(); }

Vec3 OrbitCamera::position() const { return target - forward() * distance; }

Mat4 OrbitCamera::view() const {
    const Vec3 f = forward(), r = right(), u = up(), e = position();
    Mat4 m = Mat4::Identity();
    m.block<1, 3>(0, 0) = r.transpose();
    m.block<1, 3>(1, 0) = u.transpose();
    m.block<1, 3>(2, 0) = -f.transpose();
    m(0, 3) = -r.dot(e);
    m(1, 3) = -u.dot(e);
    m(2, 3) = f.dot(e);
    return m;
}

Mat4 OrbitCamera::projection(float aspect) const {
    const float t = 1.f / std::tan(0.5f * fovY);
    Mat4 m = Mat4::Zero();
    m(0, 0) = t / std::max(aspect, 1e-6f);
    m(0, 2) = -shiftX; // x_ndc += shiftX (clip w = -z_eye)
    m(1, 1) = t;
    m(2, 2) = -(farZ + nearZ) / (farZ - nearZ);
    m(2, 3) = -2.f * farZ * nearZ / (farZ - nearZ);
    m(3, 2) = -1.f;
    return m;
}

void OrbitCamera::orbit(float dxPixels, float dyPixels) {
    yaw -= dxPixels * 0.006f;
    pitch = std::clamp(pitch + dyPixels * 0.006f, -1.5f, 1.5f);
}

void OrbitCamera::zoom(float wheelSteps) { distance = std::clamp(distance * std::pow(0.9f, wheelSteps), 0.1f, 500.f); }

void OrbitCamera::pan(float dxPixels, float dyPixels, float windowHeight) {
    const float metresPerPixel = 2.f * distance * std::tan(0.5f * fovY) / std::max(windowHeight, 1.f);
    target += (-dxPixels * right() + dyPixels * up()) * metresPerPixel;
}

void OrbitCamera::fly(const Vec3& local, float seconds) {
    // Speed grows with the distance so flying feels the same close up and far away.
    const float speed = std::max(1.f, distance) * 0.8f * seconds;
    Vec3 flatForward = forward();
    flatForward.y() = 0.f;
    if (flatForward.squaredNorm() > 1e-8f) flatForward.normalize();
    target += (local.x() * right() + local.y() * Vec3::UnitY() + local.z() * flatForward) * speed;
}

void OrbitCamera::frame(const Vec3& boxMin, const Vec3& boxMax) {
    target = 0.5f * (boxMin + boxMax);
    const float radius = std::max(0.25f, 0.5f * (boxMax - boxMin).norm());
    distance = std::clamp(radius / std::tan(0.5f * fovY) * 1.15f, 0.5f, 400.f);
    yaw = 0.35f;
    pitch = 0.18f;
}

Ray rayThroughPixel(const OrbitCamera& c, float px, float py, float width, float height) {
    const float aspect = width / std::max(height, 1.f);
    const float ndcX = 2.f * px / std::max(width, 1.f) - 1.f - c.shiftX;
    const float ndcY = 1.f - 2.f * py / std::max(height, 1.f);
    const float t = std::tan(0.5f * c.fovY);
    Ray r;
    r.origin = c.position();
    r.dir = (c.forward() + c.right() * (ndcX * t * aspect) + c.up() * (ndcY * t)).normalized();
    return r;
}

bool projectToWindow(const Mat4& vp, const Vec3& p, float width, float height, Vec2& out) {
    const Eigen::Vector4f clip = vp * Eigen::Vector4f(p.x(), p.y(), p.z(), 1.f);
    if (clip.w() <= 1e-6f) return false;
    const float x = clip.x() / clip.w(), y = clip.y() / clip.w();
    out = Vec2((x * 0.5f + 0.5f) * width, (0.5f - y * 0.5f) * height);
    return true;
}

bool rayPlane(const Ray& ray, const Vec3& point, const Vec3& normal, Vec3& hit) {
    const float denom = ray.dir.dot(normal);
    if (std::abs(denom) < 1e-8f) return false;
    const float t = (point - ray.origin).dot(normal) / denom;
    if (t < 0.f) return false;
    hit = ray.origin + t * ray.dir;
    return true;
}

void frameWorld(OrbitCamera& camera, const World& world) {
    const Cloth& c = world.cloth;
    std::vector<Vec3> finite;
    finite.reserve(c.x.size());
    for (const Vec3& x : c.x)
        if (x.allFinite()) finite.push_back(x);
    if (finite.empty()) return camera.frame(Vec3::Constant(-1.f), Vec3::Constant(1.f));
    // The median point per axis: torn scraps far away do not move it.
    Vec3 median;
    for (int a = 0; a < 3; ++a) {
        std::vector<float> coord(finite.size());
        for (size_t i = 0; i < finite.size(); ++i) coord[i] = finite[i][a];
        std::nth_element(coord.begin(), coord.begin() + coord.size() / 2, coord.end());
        median[a] = coord[coord.size() / 2];
    }
    Vec3d restLo = Vec3d::Constant(1e300), restHi = Vec3d::Constant(-1e300);
    for (const Vec3d& r : c.rest) restLo = restLo.cwiseMin(r), restHi = restHi.cwiseMax(r);
    const float reach = std::max(0.5f, 0.75f * float((restHi - restLo).norm()));
    // Torn pieces of at least kFramedShare of the rest area are framed wherever they are (a strip torn
    // off and lying on the ground); smaller ones only within reach of the median point, and scraps
    // under kScrapShare not at all: a ball's confetti on the floor beside the curtain zoomed V out
    // half as far again (the default throw at 64 a side: 29 scraps of 1-57 triangles, 0.003-0.7 %).
    constexpr double kFramedShare = 0.05, kScrapShare = 0.01;
    const std::vector<Index> label = pieceLabels(c);
    double total = 0;
    const std::vector<double> area = restAreaByLabel(c, label, total);
    Vec3 lo = Vec3::Constant(1e30f), hi = Vec3::Constant(-1e30f);
    for (Index p = 0; p < c.particleCount(); ++p) {
        const Vec3& x = c.x[p];
        if (!x.allFinite()) continue;
        const double share = label[p] != kNone ? area[label[p]] / total : 0.0;
        if (share >= kFramedShare || (share >= kScrapShare && (x - median).norm() <= reach))
            lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
    }
    for (const Ball& b : world.balls)
        if (b.x.allFinite() && (b.x - median).norm() <= reach + b.radius)
            lo = lo.cwiseMin(b.x - Vec3::Constant(b.radius)), hi = hi.cwiseMax(b.x + Vec3::Constant(b.radius));
    camera.frame(lo, hi);
}

} // namespace clothtear::app
