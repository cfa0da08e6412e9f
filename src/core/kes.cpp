// The KES material law (include/clothtear/kes.h): units, the tensile polynomial, the hysteretic
// bending rate model and the hinge that carries it. docs/kes-material.md: the source and what was
// assumed where its text is damaged.
#include "clothtear/kes.h"

#include <algorithm>
#include <cmath>

namespace clothtear {

namespace {
// The spring cap of the stability guard (src/core/step/spring_caps.h, kStiffnessCap), for hinges.
constexpr double kHingeCap = 1.0 / 3.0;
} // namespace

// The one place where KES units become SI.
KesLaw kesLawSI(const MaterialSettings& m) {
    KesLaw law;
    const double gfPerCm = kGramForce / kCentimetre; // 0.980665 N/m
    const double t[5] = {0, m.kesT1, m.kesT2, m.kesT3, m.kesT4};
    double percent = 1;
    for (int i = 1; i <= 4; ++i) {
        percent *= 100.0; // e% = 100 e: the coefficient of %^i times 100^i is that of e^i
        law.c[i] = t[i] * gfPerCm * percent;
    }
    law.D = double(m.kesBendD) * kGramForce * kCentimetre;  // gf cm^2/cm = gf cm
    law.D1 = double(m.kesBendD1) * kGramForce;              // gf cm/cm = gf
    law.alpha = double(m.kesBendAlpha) * kCentimetre;       // cm
    law.reversal = double(m.kesBendReversal);               // already 1/m (not a KES coefficient)
    return law;
}

double kesTension(const KesLaw& law, double e) {
    const double a = std::abs(e);
    const double t = a * (law.c[1] + a * (law.c[2] + a * (law.c[3] + a * law.c[4])));
    return e < 0 ? -t : t;
}

double kesTensionInRange(const KesLaw& law, double e, double range) {
    const double a = std::abs(e);
    if (a <= range) return kesTension(law, e);
    const double t = kesTension(law, range) + kesTangent(law, range) * (a - range);
    return e < 0 ? -t : t;
}

double kesTangent(const KesLaw& law, double e) {
    const double a = std::abs(e);
    return law.c[1] + a * (2 * law.c[2] + a * (3 * law.c[3] + a * 4 * law.c[4]));
}

double kesTangentInRange(const KesLaw& law, double e, double range) {
    return kesTangent(law, std::min(std::abs(e), range));
}

namespace {
// Forward Euler with the law: the step adds Rayleigh damping (kes.h).
bool kesForwardEuler(const Settings& s) {
    return s.material.model == MaterialModel::Kes && s.time.integrator == Integrator::ForwardEuler;
}
} // namespace

double kesRayleighTime(const Settings& s, double dt) { return kesForwardEuler(s) ? kKesForwardEulerDamping * dt : 0.0; }

double kesGuardWeight(const Settings& s) { return kesForwardEuler(s) ? 1.0 + 2.0 * kKesForwardEulerDamping : 1.0; }

double kesMaxTangent(const KesLaw& law, double strainMax) {
    return kesTangent(law, std::max(0.0, strainMax));
}

double kesStrainRange(const Settings& s) {
    if (s.limit.enabled) return s.limit.maxStretch;
    if (s.tear.enabled) return s.tear.threshold;
    return 0.5;
}

double kesMomentOnBranch(const KesLaw& law, const BendMemory& mem, double K) {
    const double dK = K - double(mem.reversalK);
    // direction 0 (never moved): the virgin curve from the origin, its branch by the sign of K.
    const double s = mem.direction != 0 ? double(mem.direction) : (dK >= 0 ? 1.0 : -1.0);
    return double(mem.reversalM) + law.D * dK + s * law.D1 * (1.0 - std::exp(-law.alpha * std::abs(dK)));
}

double kesSlopeOnBranch(const KesLaw& law, const BendMemory& mem, double K) {
    const double dK = K - double(mem.reversalK);
    const double s = mem.direction != 0 ? double(mem.direction) : (dK >= 0 ? 1.0 : -1.0);
    const double away = s * dK >= 0 ? 1.0 : -1.0; // -1 only on a branch K has come back past its start
    return law.D + away * law.alpha * law.D1 * std::exp(-law.alpha * std::abs(dK));
}

double kesBendAdvance(const KesLaw& law, BendMemory& mem, double K, double* slope) {
    auto on = [&](const BendMemory& branch) {
        if (slope) *slope = kesSlopeOnBranch(law, branch, K);
        return kesMomentOnBranch(law, branch, K);
    };
    const double extreme = double(mem.extremeK);
    if (K == extreme) return on(mem);
    if (mem.direction == 0) {
        // First move: the virgin curve from (reversalK, reversalM), in the direction K went.
        mem.direction = K > extreme ? 1 : -1;
        mem.extremeK = float(K);
        return on(mem);
    }
    const double s = double(mem.direction);
    if (s * (K - extreme) > 0) { // on along the branch
        mem.extremeK = float(K);
        return on(mem);
    }
    // Behind the extreme: the branch a reversal there starts (continuous in M at the extreme).
    BendMemory reversed = mem;
    reversed.reversalM = float(kesMomentOnBranch(law, mem, extreme));
    reversed.reversalK = float(extreme);
    reversed.direction = -mem.direction;
    reversed.extremeK = float(K);
    if (s * (extreme - K) > law.reversal) mem = reversed; // back far enough: the reversal counts
    return on(reversed);
}

double kesMaxBendSlope(const KesLaw& law) { return law.D + law.alpha * law.D1; }

double kesLoopEnergyPerArea(const KesLaw& law, double Km) {
    if (!(law.alpha > 0)) return 0;
    const double q = std::exp(-2 * law.alpha * Km);
    return law.D1 * (2 * Km * (1 + q) - 2 * (1 - q) / law.alpha);
}

HingeGeometry hingeOf(const Cloth& cloth, Index b) {
    const Spring& bend = cloth.bends[b];
    const Index s = cloth.bendEdge[b];
    const Spring& edge = cloth.springs[s];
    const SpringTopo& topo = cloth.springTopo[s];
    double area = 0, smallest = 0;
    for (Index t : topo.tri)
        if (t != kNone) {
            const double a = cloth.triangles[t].restArea;
            smallest = area == 0 ? a : std::min(smallest, a);
            area += a;
        }
    const double w = edge.rest;
    return HingeGeometry{bend.a, bend.b, edge.a, edge.b, w, w > 0 ? area / w : 0.0, w > 0 ? 2 * smallest / w : 0.0};
}

double kesHingeStiffness(const KesLaw& law, const HingeGeometry& h) {
    if (!(h.length > 0) || !(h.height > 0)) return 0;
    return 2 * kesMaxBendSlope(law) * h.width / (h.length * h.height * h.height);
}

// Signed angle between the two triangles' normals about the edge (0 when flat); gradient after
// Bridson et al. 2003 (their u_i with N1 = (c - a) x (c - e), N2 = (d - e) x (d - a), E = e - a):
//   d theta / dc = -|E| N1 / |N1|^2,   d theta / dd = -|E| N2 / |N2|^2,
//   d theta / da = -((c - e).E N1 / |N1|^2 + (d - e).E N2 / |N2|^2) / |E|,
//   d theta / de =  ((c - a).E N1 / |N1|^2 + (d - a).E N2 / |N2|^2) / |E|
// (signs checked against finite differences in tests/test_kes.cpp).
bool dihedralAngle(const Vec3& cf, const Vec3& df, const Vec3& af, const Vec3& ef, double& theta, Vec3d grad[4]) {
    const Vec3d c = cf.cast<double>(), d = df.cast<double>(), a = af.cast<double>(), e = ef.cast<double>();
    const Vec3d E = e - a;
    const double El = E.norm();
    const Vec3d N1 = (c - a).cross(c - e), N2 = (d - e).cross(d - a);
    const double n1 = N1.squaredNorm(), n2 = N2.squaredNorm();
    if (!(El > 1e-12) || !(n1 > 1e-24) || !(n2 > 1e-24)) return false;
    const Vec3d u1 = N1 / n1, u2 = N2 / n2;
    const double sinT = (u1.cross(u2)).dot(E) * std::sqrt(n1 * n2) / El; // (n1^ x n2^).E^
    const double cosT = u1.dot(u2) * std::sqrt(n1 * n2);                  // n1^.n2^
    theta = std::atan2(sinT, cosT);
    grad[0] = -El * u1;
    grad[1] = -El * u2;
    grad[2] = -((c - e).dot(E) * u1 + (d - e).dot(E) * u2) / El;
    grad[3] = ((c - a).dot(E) * u1 + (d - a).dot(E) * u2) / El;
    return true;
}

void materialBendForces(const Cloth& cloth, const MaterialSettings& m, std::vector<BendMemory>& memory,
                        std::vector<Vec3d>& force, std::vector<double>* moment, const HingeStep& step) {
    if (moment) moment->clear();
    if (step.tangents) step.tangents->clear();
    if (m.model == MaterialModel::Linear) {
        for (const Spring& s : cloth.bends) {
            const Vec3d d = (cloth.x[s.b] - cloth.x[s.a]).cast<double>();
            const double len = d.norm();
            if (!(len > 1e-12)) continue;
            const Vec3d f = double(m.bendStiffness) * s.weight * (len - s.rest) / len * d;
            force[s.a] += f;
            force[s.b] -= f;
        }
        return;
    }
    const KesLaw law = kesLawSI(m);
    memory.resize(cloth.bends.size());
    for (Index b = 0; b < cloth.bends.size(); ++b) {
        const HingeGeometry h = hingeOf(cloth, b);
        double theta = 0;
        Vec3d g[4];
        if (!(h.length > 0) || !dihedralAngle(cloth.x[h.c], cloth.x[h.d], cloth.x[h.a], cloth.x[h.e], theta, g)) continue;
        const double K = theta / h.length;
        double slope = 0; // only the Rayleigh damping reads it (an exp per hinge otherwise spent for nothing)
        const double M = kesBendAdvance(law, memory[b], K, step.rayleigh > 0 ? &slope : nullptr);
        if (moment) moment->push_back(M), moment->push_back(K);
        // F_i = -tau d theta / dx_i, tau = M w (the torque about the edge); dtau/dtheta = slope w / L.
        double tau = M * h.width, dTau = slope * h.width / h.length;
        const Index p[4] = {h.c, h.d, h.a, h.e};
        if (step.capDt > 0) {
            double w = 0;
            for (Index q : p) w += cloth.invMass[q];
            // a spring's k (w_a + w_b) dt^2
            const double load = 2 * step.capWeight * kesHingeStiffness(law, h) * w * step.capDt * step.capDt;
            if (load > kHingeCap) tau *= kHingeCap / load, dTau *= kHingeCap / load;
        }
        if (step.rayleigh > 0) { // tau += beta dtau/dtheta dtheta/dt (Rayleigh: C = beta K)
            double thetaRate = 0;
            for (int i = 0; i < 4; ++i) thetaRate += g[i].dot(cloth.v[p[i]].cast<double>());
            tau += step.rayleigh * dTau * thetaRate;
        }
        for (int i = 0; i < 4; ++i) force[p[i]] -= tau * g[i];
        // Implicit Euler's linearization: the largest slope, not the branch's (HingeTangent, kes.h).
        if (step.tangents)
            step.tangents->push_back(HingeTangent{{p[0], p[1], p[2], p[3]}, {g[0], g[1], g[2], g[3]},
                                                  kesMaxBendSlope(law) * h.width / h.length});
    }
}

} // namespace clothtear
