// The wind phase: quadratic drag of the relative air velocity on every triangle (Keserica 5).
#include "parallel.h"
#include "phases.h"

#include <algorithm>
#include <cmath>

namespace clothtear {

// Wind on each triangle from its normal and the relative air velocity (so a flag flutters):
//   F = c A (n . v_rel) |n . v_rel| n,   v_rel = wind - mean triangle velocity, shared by the corners,
//   A = current area, at most twice the rest area.
//
// With the stability guard on, the force on a triangle is capped so that it cannot change its
// lightest corner's normal velocity by more than the relative normal speed in one sub-step (drag
// can bring the cloth to the air's speed, not past it): explicit quadratic drag on a light cloth
// in a strong wind (rho = 0.01 kg/m^2, 30 m/s, both in the safe ranges) overshoots and explodes.
void phaseWind(const StepContext& ctx, Cloth& cloth, StepState& state) {
    const WindSettings& w = ctx.settings->wind;
    const float dt = ctx.dt;
    Vec3 dir(w.dirX, w.dirY, w.dirZ);
    if (dir.squaredNorm() < 1e-12f) return;
    dir.normalize();
    // Gusts: two incommensurate sines, deterministic in time.
    const double ph = 2.0 * M_PI * w.gustFrequency * ctx.time;
    const float gustFactor = 1.f + w.gust * float(0.65 * std::sin(ph) + 0.35 * std::sin(2.37 * ph + 1.3));
    const Vec3 wind = dir * (w.speed * std::max(0.f, gustFactor));
    const Vec3* x = cloth.x.data();
    const Vec3* v = cloth.v.data();
    const float* invMass = cloth.invMass.data();
    const bool guard = ctx.settings->time.stabilityGuard;
    const int threads = int(state.threads.acc.size());
    for (auto& r : state.threads.range) r = {0, cloth.particleCount()}; // wind may touch any particle
    parallelRegion(cloth.triangles.size(), threads, [&](int t, int nt) {
        Eigen::Vector4f* acc = state.threads.acc[t].data();
        const Chunk c = chunkOf(cloth.triangles.size(), t, nt);
        for (size_t i = c.begin; i < c.end; ++i) {
            const Triangle& tri = cloth.triangles[i];
            const Vec3 cross = (x[tri.p[1]] - x[tri.p[0]]).cross(x[tri.p[2]] - x[tri.p[0]]);
            const float twiceArea = cross.norm();
            if (!(twiceArea > 0.f)) continue;
            const Vec3 nrm = cross / twiceArea;
            const Vec3 vrel = wind - (v[tri.p[0]] + v[tri.p[1]] + v[tri.p[2]]) * (1.f / 3.f);
            const float vn = nrm.dot(vrel);
            // The corners' masses come from the rest area: a sliver torn to 1e-15 m^2 whose float
            // corners cannot get closer than ~1e-8 m would catch 10^4 times its share of wind and
            // explode (soak; also with the guard off). Its area counts up to twice the rest area.
            const float area = std::min(0.5f * twiceArea, 2.f * float(tri.restArea));
            float mag = w.dragCoefficient * area * vn * std::abs(vn) / 3.f;
            if (guard) {
                const float wMax = std::max({invMass[tri.p[0]], invMass[tri.p[1]], invMass[tri.p[2]]});
                const float cap = std::abs(vn) / (dt * std::max(wMax, 1e-30f));
                mag = std::clamp(mag, -cap, cap);
            }
            const Vec3 f = mag * nrm;
            for (Index p : tri.p) acc[p].head<3>() += f;
        }
    });
}

} // namespace clothtear
