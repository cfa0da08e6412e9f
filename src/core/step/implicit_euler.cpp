// Implicit Euler (Baraff-Witkin): assembly of the linearized system and its CG solve. See
// implicit_euler.h for the equations.
// Eigen's own OpenMP threading forks for every sparse product, however small; on a busy machine
// that made a 40x40 sub-step 60x slower. The solve runs on the calling thread.
#define EIGEN_DONT_PARALLELIZE
#include "implicit_euler.h"

#include <Eigen/IterativeLinearSolvers>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <iterator>

namespace clothtear {
namespace {

using Mat3 = Eigen::Matrix3d;
using V3 = Eigen::Vector3d;

// Offset in A's values of entry (r, col) (row-major: row r's entries are sorted by column).
int slotOf(const Eigen::SparseMatrix<double, Eigen::RowMajor>& A, int r, int col) {
    const int* inner = A.innerIndexPtr();
    const int* lo = inner + A.outerIndexPtr()[r];
    const int* hi = inner + A.outerIndexPtr()[r + 1];
    const int* it = std::lower_bound(lo, hi, col);
    return (it != hi && *it == col) ? int(it - inner) : -1;
}

void buildPattern(const Cloth& cloth, std::span<const SpringKind> kinds, ImplicitEulerCache& C,
                  Eigen::SparseMatrix<double, Eigen::RowMajor>& A) {
    const size_t n = cloth.particleCount();
    C.row.assign(n, -1);
    int unknowns = 0;
    for (Index p = 0; p < n; ++p)
        if (cloth.invMass[p] > 0.f)
            C.row[p] = unknowns, unknowns += 3;
    std::vector<Eigen::Triplet<double>> triplets;
    auto block = [&](int r, int c) {
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                triplets.emplace_back(r + i, c + j, 0.0);
    };
    for (Index p = 0; p < n; ++p)
        if (C.row[p] >= 0)
            block(C.row[p], C.row[p]);
    for (const SpringKind& kind : kinds)
        for (const Spring& s : kind.springs) {
            const int ra = C.row[s.a], rb = C.row[s.b];
            if (ra >= 0 && rb >= 0)
                block(ra, rb), block(rb, ra);
        }
    A.resize(unknowns, unknowns);
    A.setFromTriplets(triplets.begin(), triplets.end());
    A.makeCompressed();
    auto slots = [&](int r, int c, int* out) {
        for (int i = 0; i < 3; ++i)
            out[i] = (r >= 0 && c >= 0) ? slotOf(A, r + i, c) : -1;
    };
    C.diagSlots.assign(n, {-1, -1, -1});
    for (Index p = 0; p < n; ++p)
        slots(C.row[p], C.row[p], C.diagSlots[p].data());
    C.springSlots.clear();
    for (const SpringKind& kind : kinds)
        for (const Spring& s : kind.springs) {
            std::array<int, 12> o;
            const int ra = C.row[s.a], rb = C.row[s.b];
            slots(ra, ra, &o[0]);
            slots(ra, rb, &o[3]);
            slots(rb, ra, &o[6]);
            slots(rb, rb, &o[9]);
            C.springSlots.push_back(o);
        }
    C.b.setZero(unknowns);
    // A fresh cache has no dv; one restored from a world file (world_file_read.cpp) brings the
    // saved warm start, which the solve below must see to continue bit for bit.
    if (C.dv.size() != unknowns)
        C.dv.setZero(unknowns);
}

// kes hinges (implicit_euler.h): H = (dtau/dtheta) g g^T over the four corners, dt^2 H into A and
// -dt^2 H v into b (their forces are in the step's external force). The blocks' slots are found in
// A's rows (a hinge's corners are all joined by springs: the pattern has every pair).
void addHinges(std::span<const HingeTangent> hinges, double dt, const Cloth& cloth, ImplicitEulerCache& C,
               Eigen::SparseMatrix<double, Eigen::RowMajor>& A) {
    double* val = A.valuePtr();
    for (const HingeTangent& h : hinges) {
        if (!(h.stiffness > 0))
            continue;
        double rate = 0; // dtheta/dt
        for (int i = 0; i < 4; ++i)
            rate += h.grad[i].dot(cloth.v[h.p[i]].cast<double>());
        const double c = dt * dt * h.stiffness;
        for (int i = 0; i < 4; ++i) {
            const int ri = C.row[h.p[i]];
            if (ri < 0)
                continue;
            C.b.segment<3>(ri) -= c * rate * h.grad[i];
            for (int j = 0; j < 4; ++j) {
                const int rj = C.row[h.p[j]];
                if (rj < 0)
                    continue;
                const Mat3 B = c * h.grad[i] * h.grad[j].transpose();
                for (int r = 0; r < 3; ++r) {
                    const int slot = slotOf(A, ri + r, rj);
                    assert(slot >= 0 && "a hinge's corners are joined in the pattern");
                    if (slot < 0)
                        continue;
                    for (int col = 0; col < 3; ++col)
                        val[slot + col] += B(r, col);
                }
            }
        }
    }
}

} // namespace

void implicitEulerStep(Cloth& cloth, const ReferenceStepInput& in, const ImplicitEulerOptions& options,
                       ImplicitEulerCache& C) {
    const size_t n = cloth.particleCount();
    const double dt = in.dt;
    Eigen::SparseMatrix<double, Eigen::RowMajor>& A = C.A;
    if (!C.built) {
        buildPattern(cloth, in.kinds, C, A);
        C.built = true;
    }
    const int unknowns = int(A.rows());
    double* val = A.valuePtr();
    std::fill(val, val + A.nonZeros(), 0.0);
    C.b.setZero();

    // Per particle: mass and air drag on the diagonal, gravity, drag and other phases' forces.
    std::vector<V3>& f = C.force;
    f.assign(n, V3::Zero());
    for (Index p = 0; p < n; ++p) {
        if (C.row[p] < 0)
            continue;
        const double m = 1.0 / cloth.invMass[p];
        const V3 v = cloth.v[p].cast<double>();
        f[p] = m * (in.gravity.cast<double>() - double(in.dragPerMass) * v);
        if (!in.force.empty())
            f[p] += in.force[p].cast<double>();
        const double d = m * (1.0 + dt * in.dragPerMass);
        for (int i = 0; i < 3; ++i)
            val[C.diagSlots[p][i] + i] += d;
    }

    // Springs: forces, and the blocks dt D + dt^2 K (as positive matrices H = -K, B = -D).
    size_t si = 0;
    for (size_t ki = 0; ki < std::size(in.kinds); ++ki) {
        const SpringKind& kind = in.kinds[ki];
        const bool law = ki == 0 && in.kes; // kes: the structural springs follow the tensile law
        for (const Spring& s : kind.springs) {
            const std::array<int, 12>& o = C.springSlots[si++];
            const double k = double(kind.stiffness) * s.weight, kd = double(kind.damping) * s.weight;
            if (k == 0.0 && kd == 0.0 && !law)
                continue;
            const V3 d = (cloth.x[s.b] - cloth.x[s.a]).cast<double>();
            const double l = d.norm();
            if (!(l > 1e-12))
                continue;
            const V3 nrm = d / l;
            const V3 vab = (cloth.v[s.b] - cloth.v[s.a]).cast<double>();
            const Mat3 nn = nrm * nrm.transpose();
            V3 fa;
            Mat3 H;
            if (law) {
                const double e = (l - s.rest) / s.rest;
                const double F = kesTensionInRange(*in.kes, e, in.kesRange) * s.weight * s.rest;
                fa = (F + kd * vab.dot(nrm)) * nrm;
                H = kesTangentInRange(*in.kes, e, in.kesRange) * s.weight * nn +
                    std::max(0.0, F / l) * (Mat3::Identity() - nn);
            } else {
                fa = (k * (l - s.rest) + kd * vab.dot(nrm)) * nrm;
                const double geo = std::max(0.0, 1.0 - s.rest / l);
                H = k * (nn + geo * (Mat3::Identity() - nn));
            }
            f[s.a] += fa;
            f[s.b] -= fa;
            const Mat3 B = dt * kd * nn + dt * dt * H;
            // dt^2 K v on each end: -dt^2 H (v_a - v_b) for a, the opposite for b.
            const V3 hv = dt * dt * (H * vab); // = -dt^2 H (v_a - v_b)
            if (C.row[s.a] >= 0)
                C.b.segment<3>(C.row[s.a]) += hv;
            if (C.row[s.b] >= 0)
                C.b.segment<3>(C.row[s.b]) -= hv;
            for (int blk = 0; blk < 4; ++blk) {
                if (o[3 * blk] < 0)
                    continue;
                const double sign = (blk == 0 || blk == 3) ? 1.0 : -1.0;
                for (int i = 0; i < 3; ++i)
                    for (int j = 0; j < 3; ++j)
                        val[o[3 * blk + i] + j] += sign * B(i, j);
            }
        }
    }
    addHinges(in.hinges, dt, cloth, C, A);
    for (Index p = 0; p < n; ++p)
        if (C.row[p] >= 0)
            C.b.segment<3>(C.row[p]) += dt * f[p];

    Eigen::ConjugateGradient<Eigen::SparseMatrix<double, Eigen::RowMajor>, Eigen::Lower | Eigen::Upper,
                             Eigen::DiagonalPreconditioner<double>>
        cg;
    cg.setTolerance(options.tolerance);
    cg.setMaxIterations(options.maxIterations);
    cg.compute(A);
    if (C.dv.size() != unknowns)
        C.dv.setZero(unknowns);
    C.dv = cg.solveWithGuess(C.b, C.dv); // last step's dv is a good first guess
    C.lastIterations = int(cg.iterations());
    C.lastError = cg.error();

    for (Index p = 0; p < n; ++p) {
        if (C.row[p] < 0)
            continue;
        const V3 v = (cloth.v[p].cast<double>() + C.dv.segment<3>(C.row[p])) * double(in.keep);
        cloth.v[p] = v.cast<float>();
        cloth.x[p] = (cloth.x[p].cast<double>() + dt * v).cast<float>();
    }
}

} // namespace clothtear
