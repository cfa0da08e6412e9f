// The frame of a mesh (mesh.h): its plane by a principal-axis fit, "up" and "right" in it.
#include "clothtear/mesh.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace clothtear {
namespace {

// Round-off of the fit leaves 1e-17 where a built-in mesh has 0: snap it, so their pins, hands and
// balls sit exactly where the world axes put them.
Vec3d snapped(const Vec3d& axis) {
    for (int i = 0; i < 3; ++i)
        if (std::abs(std::abs(axis[i]) - 1.0) < 1e-9) return Vec3d::Unit(i) * (axis[i] < 0 ? -1.0 : 1.0);
    return axis;
}

} // namespace

MeshFrame meshFrame(const std::vector<Vec3d>& points) {
    MeshFrame f;
    if (points.empty()) return f;
    for (const Vec3d& p : points) f.centre += p;
    f.centre /= double(points.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (const Vec3d& p : points) cov += (p - f.centre) * (p - f.centre).transpose();
    // The normal is the direction of least spread (eigenvalues come in increasing order).
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    Vec3d n = eig.info() == Eigen::Success ? Vec3d(eig.eigenvectors().col(0)) : Vec3d::UnitZ();
    if (!n.allFinite() || n.squaredNorm() == 0.0) n = Vec3d::UnitZ();
    n = snapped(n.normalized());
    // Upright meshes face the camera (+z); flat ones face up; one seen edge-on from +z faces +x.
    const bool flat = std::abs(n.y()) > 0.7;
    const int facing = flat ? 1 : (std::abs(n.z()) >= std::abs(n.x()) ? 2 : 0);
    if (n[facing] < 0) n = -n;
    const Vec3d wanted = flat ? Vec3d(-Vec3d::UnitZ()) : Vec3d(Vec3d::UnitY());
    Vec3d up = wanted - wanted.dot(n) * n;
    f.normal = n;
    f.up = snapped(up.normalized());
    f.right = snapped(f.up.cross(f.normal).normalized());
    f.minU = f.minV = 1e300;
    f.maxU = f.maxV = -1e300;
    for (const Vec3d& p : points) {
        f.minU = std::min(f.minU, f.u(p)), f.maxU = std::max(f.maxU, f.u(p));
        f.minV = std::min(f.minV, f.v(p)), f.maxV = std::max(f.maxV, f.v(p));
    }
    return f;
}

} // namespace clothtear
