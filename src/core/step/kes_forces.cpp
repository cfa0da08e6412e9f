// material.model = kes in the step (include/clothtear/kes.h, docs/kes-material.md): the structural
// springs follow the KES-FB1 tensile law, F = T(e) x width along the spring (Tagawa Eq. 1), and a
// hinge per interior edge the hysteretic bending rate model (Eq. 3), whose memory (Cloth::bendMemory)
// advances once per sub-step, here. One thread: the scenes that use it are strips of a few hundred
// particles (docs/kes-material.md has the cost).
#include "clothtear/kes.h"
#include "phases.h"

#include <algorithm>
#include <cmath>

namespace clothtear {
namespace {

// Structural springs: f = (T(e) width + kd (v_b - v_a).n) n + beta K_t (v_b - v_a) with
// e = (L - L0) / L0 (T continued linearly past the guard's strain range, kesTensionInRange), on end a
// (end b gets -f). `width` is the cache's kesWidth (weight x rest, times what the guard kept); beta
// the Rayleigh time of forward Euler (kesRayleighTime, kes.h; 0 otherwise) and K_t the spring's
// tangent stiffness, T'(e) width / L0 along n and, stretched, F / l across (the geometric term: the
// sideways modes of a stretched spring, undamped along n alone, grew in a cloth the ground had
// pulled to 800 % strain, tests/test_stability.cpp). T convex from 0 keeps F / l below T' width / L0,
// so the guard's count of T' (kesGuardWeight) covers both.
template <class Add>
void tensionForces(const KesLaw& law, double range, double beta, const SpringCache& S, const Cloth& cloth, Add&& add) {
    for (size_t i = 0; i < S.structural; ++i) {
        const Index a = S.a16[i] / 16, b = S.b16[i] / 16;
        const Vec3 d = cloth.x[b] - cloth.x[a];
        const float len = d.norm();
        if (!(len > 1e-12f)) continue;
        const Vec3 n = d / len;
        const double e = (double(len) - S.rest[i]) / S.rest[i];
        const Vec3 dv = cloth.v[b] - cloth.v[a];
        const float dvd = dv.dot(n);
        const double F = kesTensionInRange(law, e, range) * S.kesWidth[i];
        Vec3 f = (float(F) + S.kd[i] * dvd) * n;
        if (beta > 0) {
            const double along = beta * kesTangentInRange(law, e, range) * S.kesWidth[i] / S.rest[i];
            const double across = beta * std::max(0.0, F) / len;
            f += float(along) * dvd * n + float(across) * (dv - dvd * n);
        }
        add(a, f);
        add(b, Vec3(-f));
    }
}

void hinges(const StepContext& ctx, Cloth& cloth, std::vector<Vec3d>& force, std::vector<HingeTangent>* implicit = nullptr) {
    if (cloth.bendMemory.size() != cloth.bends.size()) {
        // First kes step of this cloth (or after a switch from linear): every hinge starts at rest.
        // Afterwards the topology changes keep the memory parallel to the bends (cloth.cpp).
        cloth.bendMemory.assign(cloth.bends.size(), BendMemory{});
    }
    force.assign(cloth.particleCount(), Vec3d::Zero());
    const Settings& s = *ctx.settings;
    HingeStep step;
    step.capDt = s.time.stabilityGuard && !implicit ? double(ctx.dt) : 0.0; // implicit Euler: stable uncapped
    step.capWeight = kesGuardWeight(s);
    step.rayleigh = kesRayleighTime(s, ctx.dt);
    step.tangents = implicit;
    materialBendForces(cloth, s.material, cloth.bendMemory, force, nullptr, step);
}

} // namespace

void phaseSpringsKes(const StepContext& ctx, Cloth& cloth, StepState& state) {
    const SpringCache& S = state.springs;
    const size_t n = cloth.particleCount();
    for (size_t p = 0; p < n; ++p) state.packed[p] = packedOf(cloth.x[p], cloth.v[p]);
    state.threads.range.assign(state.threads.acc.size(), {n, 0});
    state.threads.range[0] = {0, n};
    Eigen::Vector4f* acc = state.threads.acc[0].data();
    const KesLaw law = kesLawSI(ctx.settings->material);
    tensionForces(law, kesStrainRange(*ctx.settings), kesRayleighTime(*ctx.settings, ctx.dt), S, cloth, [&](Index p, const Vec3& f) { acc[p].head<3>() += f; });
    std::vector<Vec3d>& hingeForce = state.kesHingeForce;
    hinges(ctx, cloth, hingeForce);
    for (size_t p = 0; p < n; ++p) acc[p].head<3>() += hingeForce[p].cast<float>();
}

void kesForces(const StepContext& ctx, Cloth& cloth, StepState& state, std::vector<Vec3>& force,
               std::vector<HingeTangent>* implicit) {
    if (force.size() != cloth.particleCount()) force.assign(cloth.particleCount(), Vec3::Zero());
    const KesLaw law = kesLawSI(ctx.settings->material);
    if (!implicit)
        tensionForces(law, kesStrainRange(*ctx.settings), 0.0, state.springs, cloth, [&](Index p, const Vec3& f) { force[p] += f; });
    std::vector<Vec3d>& hingeForce = state.kesHingeForce;
    hinges(ctx, cloth, hingeForce, implicit);
    for (size_t p = 0; p < force.size(); ++p) force[p] += hingeForce[p].cast<float>();
}

} // namespace clothtear
