// material.model = kes in the step (include/clothtear/kes.h, docs/kes-material.md): the structural
// springs follow the KES-FB1 tensile law, F = T(e) x width along the spring (Tagawa Eq. 1), and a
// hinge per interior edge the hysteretic bending rate model (Eq. 3), whose memory (Cloth::bendMemory)
// advances once per sub-step, here. One thread: the scenes that use it are strips of a few hundred
// particles (docs/kes-material.md has the cost).
#include "clothtear/kes.h"
#include "phases.h"

#include <cmath>

namespace clothtear {
namespace {

// Structural springs: f = (T(e) width + kd (v_b - v_a).n) n with e = (L - L0) / L0 (T continued
// linearly past the guard's strain range, kesTensionInRange), on end a
// (end b gets -f). `width` is the cache's kesWidth (weight x rest, times what the guard kept).
template <class Add>
void tensionForces(const KesLaw& law, double range, const SpringCache& S, const Cloth& cloth, Add&& add) {
    for (size_t i = 0; i < S.structural; ++i) {
        const Index a = S.a16[i] / 16, b = S.b16[i] / 16;
        const Vec3 d = cloth.x[b] - cloth.x[a];
        const float len = d.norm();
        if (!(len > 1e-12f)) continue;
        const Vec3 n = d / len;
        const double e = (double(len) - S.rest[i]) / S.rest[i];
        const float dvd = (cloth.v[b] - cloth.v[a]).dot(n);
        const Vec3 f = (float(kesTensionInRange(law, e, range) * S.kesWidth[i]) + S.kd[i] * dvd) * n;
        add(a, f);
        add(b, Vec3(-f));
    }
}

void hinges(const StepContext& ctx, Cloth& cloth, std::vector<Vec3d>& force) {
    if (cloth.bendMemory.size() != cloth.bends.size()) {
        // First kes step of this cloth (or after a switch from linear): every hinge starts at rest.
        // Afterwards the topology changes keep the memory parallel to the bends (cloth.cpp).
        cloth.bendMemory.assign(cloth.bends.size(), BendMemory{});
    }
    force.assign(cloth.particleCount(), Vec3d::Zero());
    const double capDt = ctx.settings->time.stabilityGuard ? double(ctx.dt) : 0.0;
    materialBendForces(cloth, ctx.settings->material, cloth.bendMemory, force, nullptr, capDt);
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
    tensionForces(law, kesStrainRange(*ctx.settings), S, cloth, [&](Index p, const Vec3& f) { acc[p].head<3>() += f; });
    std::vector<Vec3d>& hingeForce = state.kesHingeForce;
    hinges(ctx, cloth, hingeForce);
    for (size_t p = 0; p < n; ++p) acc[p].head<3>() += hingeForce[p].cast<float>();
}

void kesForces(const StepContext& ctx, Cloth& cloth, StepState& state, std::vector<Vec3>& force) {
    if (force.size() != cloth.particleCount()) force.assign(cloth.particleCount(), Vec3::Zero());
    const KesLaw law = kesLawSI(ctx.settings->material);
    tensionForces(law, kesStrainRange(*ctx.settings), state.springs, cloth, [&](Index p, const Vec3& f) { force[p] += f; });
    std::vector<Vec3d>& hingeForce = state.kesHingeForce;
    hinges(ctx, cloth, hingeForce);
    for (size_t p = 0; p < force.size(); ++p) force[p] += hingeForce[p].cast<float>();
}

} // namespace clothtear
