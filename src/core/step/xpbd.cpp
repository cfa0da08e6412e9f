// XPBD with small steps: one Gauss-Seidel pass over the springs per sub-step. See xpbd.h.
#include "xpbd.h"

#include <cmath>

namespace clothtear {

void xpbdStep(Cloth& cloth, const ReferenceStepInput& in, std::vector<Vec3>& dx) {
    const size_t n = cloth.particleCount();
    const float dt = in.dt;
    dx.resize(n);
    Vec3* x = cloth.x.data();
    Vec3* v = cloth.v.data();
    const float* w = cloth.invMass.data();
    // Predict: external accelerations (gravity, air drag, wind) as in semi-implicit Euler.
    for (Index p = 0; p < n; ++p) {
        if (w[p] == 0.f) {
            dx[p] = Vec3::Zero();
            continue;
        }
        Vec3 a = in.gravity - in.dragPerMass * v[p];
        if (!in.force.empty())
            a += in.force[p] * w[p];
        v[p] = (v[p] + a * dt) * in.keep;
        dx[p] = v[p] * dt;
    }
    // One constraint pass (Macklin et al. 2019: one iteration, many sub-steps) on the
    // displacements dx = x - x_n.
    for (const SpringKind& kind : in.kinds) {
        if (kind.stiffness == 0.f && kind.damping == 0.f)
            continue;
        for (const Spring& s : kind.springs) {
            const float wa = w[s.a], wb = w[s.b];
            if (wa + wb == 0.f)
                continue;
            const Vec3 rel = dx[s.b] - dx[s.a];
            const Vec3 d = (x[s.b] - x[s.a]) + rel;
            const float l = d.norm();
            if (!(l > 1e-12f))
                continue;
            const Vec3 nrm = d / l;
            const float kdt2 = kind.stiffness * s.weight * dt * dt, kddt = kind.damping * s.weight * dt;
            // grad C . (x - x_n): how far the ends moved apart along n since the step began.
            const float dl = (-kdt2 * (l - s.rest) - kddt * nrm.dot(rel)) / ((kdt2 + kddt) * (wa + wb) + 1.f);
            dx[s.a] -= (wa * dl) * nrm;
            dx[s.b] += (wb * dl) * nrm;
        }
    }
    const float invDt = 1.f / dt;
    for (Index p = 0; p < n; ++p) {
        if (w[p] == 0.f)
            continue;
        v[p] = dx[p] * invDt;
        x[p] += dx[p];
    }
}

} // namespace clothtear
