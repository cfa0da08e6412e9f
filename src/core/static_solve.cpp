// Newton's method on the spring network's potential energy (static_solve.h).
//
// Per spring (d = x_b - x_a, l = |d|, n = d / l): the gradient on a is -k (l - L) n and the Hessian
// block (a, a) is k (n n^T + (1 - L / l)(I - n n^T)), with (a, b) its negative. A compressed spring
// makes the second term negative and the Hessian may be indefinite (a hanging sheet is close to
// buckling sideways); where its step is not a descent the solve uses the clamped Hessian (that
// term dropped where negative, Choi & Ko 2002), positive semi-definite. A backtracking line
// search on E keeps every step a decrease.
#include "clothtear/static_solve.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <cmath>

namespace clothtear {
namespace {

using V3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

struct Model {
    const Cloth& cloth;
    std::vector<int> row; // first unknown of each free particle, -1 if pinned
    V3 g;
    double ks[2]; // stiffness per unit weight: structural, bend-shear

    const std::vector<Spring>& springs(int kind) const { return kind == 0 ? cloth.springs : cloth.bends; }

    double energy(const std::vector<V3>& x) const {
        double e = 0;
        for (int kind = 0; kind < 2; ++kind)
            for (const Spring& s : springs(kind)) {
                const double ext = (x[s.b] - x[s.a]).norm() - s.rest;
                e += 0.5 * ks[kind] * s.weight * ext * ext;
            }
        for (Index p = 0; p < cloth.particleCount(); ++p)
            e -= cloth.particleMass(p) * g.dot(x[p]);
        return e;
    }

    // Gradient of E over the unknowns.
    Eigen::VectorXd gradient(const std::vector<V3>& x, int unknowns) const {
        Eigen::VectorXd grad = Eigen::VectorXd::Zero(unknowns);
        for (int kind = 0; kind < 2; ++kind)
            for (const Spring& s : springs(kind)) {
                const V3 d = x[s.b] - x[s.a];
                const double l = d.norm();
                if (!(l > 0))
                    continue;
                const V3 f = ks[kind] * s.weight * (l - s.rest) / l * d; // pull on a towards b
                if (row[s.a] >= 0)
                    grad.segment<3>(row[s.a]) -= f;
                if (row[s.b] >= 0)
                    grad.segment<3>(row[s.b]) += f;
            }
        for (Index p = 0; p < cloth.particleCount(); ++p)
            if (row[p] >= 0)
                grad.segment<3>(row[p]) -= cloth.particleMass(p) * g;
        return grad;
    }

    Eigen::SparseMatrix<double> hessian(const std::vector<V3>& x, int unknowns, bool clamp,
                                        double shift) const {
        std::vector<Eigen::Triplet<double>> t;
        t.reserve(36 * (cloth.springs.size() + cloth.bends.size()) + 3 * size_t(unknowns));
        auto block = [&](int r, int c, const Mat3& B) {
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                    t.emplace_back(r + i, c + j, B(i, j));
        };
        for (int kind = 0; kind < 2; ++kind)
            for (const Spring& s : springs(kind)) {
                const double k = ks[kind] * s.weight;
                if (k == 0)
                    continue;
                const V3 d = x[s.b] - x[s.a];
                const double l = d.norm();
                if (!(l > 0))
                    continue;
                const V3 n = d / l;
                const Mat3 nn = n * n.transpose();
                double geo = 1.0 - s.rest / l;
                if (clamp)
                    geo = std::max(0.0, geo);
                const Mat3 B = k * (nn + geo * (Mat3::Identity() - nn));
                const int ra = row[s.a], rb = row[s.b];
                if (ra >= 0)
                    block(ra, ra, B);
                if (rb >= 0)
                    block(rb, rb, B);
                if (ra >= 0 && rb >= 0)
                    block(ra, rb, -B), block(rb, ra, -B);
            }
        for (int i = 0; i < unknowns; ++i)
            t.emplace_back(i, i, shift);
        Eigen::SparseMatrix<double> H(unknowns, unknowns);
        H.setFromTriplets(t.begin(), t.end());
        return H;
    }
};

} // namespace

StaticSolveResult solveStatic(const Cloth& cloth, const Settings& settings, std::span<const Vec3> start,
                              const StaticSolveOptions& options) {
    StaticSolveResult r;
    const size_t n = cloth.particleCount();
    Model M{cloth,
            std::vector<int>(n, -1),
            V3(settings.gravity.x, settings.gravity.y, settings.gravity.z),
            {settings.material.stretchStiffness, settings.material.bendStiffness}};
    int unknowns = 0;
    double weight = 0;
    for (Index p = 0; p < n; ++p) {
        if (!cloth.pinned(p))
            M.row[p] = unknowns, unknowns += 3;
        weight += cloth.particleMass(p) * M.g.norm();
    }
    weight = std::max(weight, 1e-30);
    std::vector<V3> x(n);
    for (Index p = 0; p < n; ++p)
        x[p] = start[p].cast<double>();
    // A tiny shift keeps directions no spring resists (a slack region) solvable; 1e-12 of the
    // stiffest spring changes nothing else.
    double kMax = 0;
    for (int kind = 0; kind < 2; ++kind)
        for (const Spring& s : M.springs(kind))
            kMax = std::max(kMax, M.ks[kind] * s.weight);
    const double shift = 1e-12 * std::max(kMax, 1e-30);

    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
    bool analyzed = false;
    double e = M.energy(x);
    for (r.iterations = 0; r.iterations < options.maxIterations; ++r.iterations) {
        const Eigen::VectorXd grad = M.gradient(x, unknowns);
        r.residual = grad.norm() / weight;
        if (r.residual <= options.tolerance) {
            r.converged = true;
            break;
        }
        // The exact Hessian when its Newton step goes downhill, else the clamped one. An
        // indefinite exact Hessian still gives a good step when the negative directions carry no
        // gradient: a compressed spring of a flat hanging sheet is negative only out of the plane,
        // where the gradient is zero (measured: 5-8 iterations to 1e-9 at 16..128; clamping from
        // the start took over 100 at 32x32).
        Eigen::VectorXd dir;
        for (bool clamp : {false, true}) {
            const Eigen::SparseMatrix<double> H = M.hessian(x, unknowns, clamp, shift);
            if (!analyzed)
                ldlt.analyzePattern(H), analyzed = true; // same pattern every iteration
            ldlt.factorize(H);
            if (ldlt.info() != Eigen::Success)
                continue;
            dir = -ldlt.solve(grad);
            if (dir.allFinite() && grad.dot(dir) < 0)
                break;
            dir.resize(0);
        }
        if (dir.size() == 0) {
            r.error = "static solve: no descent direction (factorization failed)";
            break;
        }
        // Backtracking (Armijo) line search on E.
        double step = 1;
        std::vector<V3> trial(n);
        bool accepted = false;
        for (int ls = 0; ls < 40; ++ls, step *= 0.5) {
            for (Index p = 0; p < n; ++p)
                trial[p] = M.row[p] >= 0 ? V3(x[p] + step * dir.segment<3>(M.row[p])) : x[p];
            const double et = M.energy(trial);
            if (et <= e + 1e-4 * step * grad.dot(dir)) {
                x.swap(trial);
                e = et;
                accepted = true;
                break;
            }
        }
        if (!accepted) {
            // No decrease representable in double: the gradient left is round-off.
            r.converged = r.residual <= 1e3 * options.tolerance;
            break;
        }
    }
    r.x = std::move(x);
    return r;
}

} // namespace clothtear
