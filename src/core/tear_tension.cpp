// The fabric's tension axis round a tear tip (tear_tension.h). Why not the tense spring's direction,
// as Onal 3.2.2 takes it: on a grid that spring lies along one of four lattice directions, so the
// axis jumps between them, and which spoke lies "closest to the perpendicular" is often a near tie
// that round-off decides. The pull scene torn sideways ran its rip 1.5 m or 3.5 m by 5 s at 80 a
// side with hand speeds 1e-4 m/s apart, and 1.85 / 2.10 / 3.44 m at 40 / 80 / 160 (issue 13 goal 1;
// bench/README.md, "The tear tip reads the fabric's tension"). A crack in a continuum runs across
// its largest principal stress, read over a length of material, not over one spring: the same metres
// of fabric at every resolution.
#include "tear_tension.h"

#include <Eigen/Eigenvalues>

#include <vector>

namespace clothtear {
namespace {

// The triangle's tensile strain pushed forward, times its rest area, added to B.
void addTensileStrain(const Cloth& c, const Triangle& t, Eigen::Matrix3d& B) {
    // Rest edges in the triangle's own orthonormal frame (u, w): Dm = [[l1, E2.u], [0, l2]], and the
    // deformation gradient F = Ds Dm^-1 maps them to the current edges Ds (3 x 2).
    const Vec3d E1 = c.rest[t.p[1]] - c.rest[t.p[0]], E2 = c.rest[t.p[2]] - c.rest[t.p[0]];
    const double l1 = E1.norm();
    if (!(l1 > 0.0)) return;
    const Vec3d u = E1 / l1;
    const double along = E2.dot(u);
    const double l2 = (E2 - along * u).norm();
    if (!(l2 > 0.0)) return;
    const Vec3d e1 = (c.x[t.p[1]] - c.x[t.p[0]]).cast<double>(), e2 = (c.x[t.p[2]] - c.x[t.p[0]]).cast<double>();
    Eigen::Matrix<double, 3, 2> F;
    F.col(0) = e1 / l1;
    F.col(1) = (e2 - (along / l1) * e1) / l2;
    const Eigen::Matrix2d green = 0.5 * (F.transpose() * F - Eigen::Matrix2d::Identity());
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> principal;
    principal.computeDirect(green);
    for (int k = 0; k < 2; ++k) {
        const double stretch = principal.eigenvalues()[k];
        if (!(stretch > 0.0)) continue; // compression (and NaN) does not steer a tear
        const Vec3d now = F * principal.eigenvectors().col(k);
        const double n2 = now.squaredNorm();
        if (n2 > 0.0) B += (t.restArea * stretch / n2) * (now * now.transpose());
    }
}

} // namespace

Vec3 fabricTensionAxis(const Cloth& c, Index p, std::span<const Index> fanTriangles, float radius) {
    if (!(radius > 0.f)) return Vec3::Zero();
    // Breadth first over triangles sharing a particle (a tear's walls separate them), from the fan.
    std::vector<uint8_t> seen(c.triangles.size(), 0);
    std::vector<Index> fabric(fanTriangles.begin(), fanTriangles.end());
    for (Index t : fabric) seen[t] = 1;
    const Vec3d tip = c.rest[p];
    const double r2 = double(radius) * double(radius);
    for (size_t next = 0; next < fabric.size(); ++next)
        for (Index q : c.triangles[fabric[next]].p) {
            if (c.pinned(q)) return Vec3::Zero();
            for (Index u : c.particleTris[q]) {
                if (seen[u]) continue;
                seen[u] = 1;
                const Triangle& t = c.triangles[u];
                const Vec3d centroid = (c.rest[t.p[0]] + c.rest[t.p[1]] + c.rest[t.p[2]]) / 3.0;
                if ((centroid - tip).squaredNorm() <= r2) fabric.push_back(u);
            }
        }
    Eigen::Matrix3d B = Eigen::Matrix3d::Zero();
    for (Index t : fabric) addTensileStrain(c, c.triangles[t], B);
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> principal;
    principal.computeDirect(B);
    const Eigen::Vector3d lambda = principal.eigenvalues(); // ascending
    // No tension, or two directions stretched alike (within round-off): no single axis.
    if (!(lambda[2] > 0.0) || lambda[2] - lambda[1] <= 1e-6 * lambda[2]) return Vec3::Zero();
    return principal.eigenvectors().col(2).normalized().cast<float>();
}

} // namespace clothtear
