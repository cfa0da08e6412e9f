// The world's setup: building the cloth, pinning, settings; and what a user does from outside the
// step (impulses) or asks of it (energies). The step itself is in src/core/step/ (step.cpp).
#include "clothtear/world.h"

#include "step/phases.h"
#include "step/step_state.h"

#include <algorithm>
#include <cmath>

namespace clothtear {

std::string World::rebuild() {
    const ClothSettings& c = settings.cloth;
    if (c.mesh == MeshType::Obj) return rebuild(restMesh);
    MeshData mesh = c.mesh == MeshType::Grid
                        ? makeGridMesh(c.resolutionX, c.resolutionY, c.width, c.height)
                        : makeIrregularMesh(c.resolutionX, c.resolutionY, c.width, c.height, c.jitter, uint32_t(c.seed));
    return rebuild(mesh);
}

std::string World::rebuild(const MeshData& mesh) {
    Result<Cloth> built = buildCloth(mesh, settings.material.density);
    if (!built.ok()) return built.error;
    if (&mesh != &restMesh) restMesh = mesh;
    restFrame = knifeFrame(restMesh.positions);
    cloth = std::move(built.value);
    state_ = StepStateBox{}; // the caches of the step belong to the old cloth
    // Tilt about the top edge: 0 deg hangs in the x-y plane, 90 deg lies horizontal towards +z.
    if (settings.cloth.tilt != 0.f) {
        float top = -1e30f;
        for (const Vec3& x : cloth.x) top = std::max(top, x.y());
        const float a = settings.cloth.tilt * float(M_PI / 180.0);
        for (Vec3& x : cloth.x) {
            const float dy = x.y() - top;
            x = Vec3(x.x(), top + dy * std::cos(a), x.z() - dy * std::sin(a));
        }
    }
    balls.clear();
    drivers.clear();
    tearLog = TearLog{};
    profile.reset();
    time = 0;
    steps = 0;
    maxStrain = 0;
    wake();
    sleptFrames = 0;
    finite = true;
    nonFiniteWhere.clear();
    pinByMode(settings.cloth.pin);
    return {};
}

void World::resetStepState() { state_ = StepStateBox{}; }

void World::applySettings() {
    if (cloth.density != settings.material.density) cloth.setDensity(settings.material.density);
}

void World::pinByMode(PinMode mode) {
    const size_t n = cloth.particleCount();
    for (Index p = 0; p < n; ++p) cloth.setPinned(p, false), cloth.flags[p] &= uint8_t(~kHem);
    if (mode == PinMode::None || n == 0) return;
    // Edges and corners of the mesh's own extent in its plane (a flat OBJ has a top edge too).
    const MeshFrame f = meshFrame(cloth.rest);
    const double eps = 1e-6 * std::max(1.0, f.width());
    // What the pin mode pins is a hem (kHem): stronger than the cloth (tear.seam_strength).
    auto pin = [&](Index p) {
        cloth.setPinned(p, true);
        cloth.flags[p] |= kHem;
    };
    auto pinIf = [&](auto&& onEdge) {
        for (Index p = 0; p < n; ++p)
            if (onEdge(f.u(cloth.rest[p]), f.v(cloth.rest[p]))) pin(p);
    };
    if (mode == PinMode::TopEdge) {
        pinIf([&](double, double v) { return v > f.maxV - eps; });
    } else if (mode == PinMode::LeftEdge) {
        pinIf([&](double u, double) { return u < f.minU + eps; });
    } else if (mode == PinMode::LeftRightEdges) {
        pinIf([&](double u, double) { return u < f.minU + eps || u > f.maxU - eps; });
    } else if (mode == PinMode::TopCorners) {
        // The particles closest to the two top corners.
        Index best[2] = {0, 0};
        double bestD[2] = {1e300, 1e300};
        for (Index p = 0; p < n; ++p) {
            const double u = f.u(cloth.rest[p]), v = f.v(cloth.rest[p]);
            const double dl = (u - f.minU) * (u - f.minU) + (v - f.maxV) * (v - f.maxV);
            const double dr = (u - f.maxU) * (u - f.maxU) + (v - f.maxV) * (v - f.maxV);
            if (dl < bestD[0]) bestD[0] = dl, best[0] = p;
            if (dr < bestD[1]) bestD[1] = dr, best[1] = p;
        }
        pin(best[0]);
        pin(best[1]);
    }
}

CutResult World::cut(const std::vector<Vec2d>& stroke) {
    std::vector<std::pair<Index, Index>> copies;
    const TearContext ctx{settings.tear, time, &tearLog, &copies};
    CutResult result = cutAlong(cloth, restFrame, stroke, ctx);
    if (result.particlesAdded > 0) {
        driversFollowCopies(drivers, copies);
        wake();
    }
    return result;
}

int World::applyImpulse(const Vec3& center, float radius, const Vec3& direction, float dv) {
    Vec3 dir = direction;
    if (dir.squaredNorm() == 0.f) return 0;
    dir.normalize();
    wake();
    int hit = 0;
    for (Index p = 0; p < cloth.particleCount(); ++p) {
        if (cloth.invMass[p] == 0.f || (cloth.x[p] - center).squaredNorm() > radius * radius) continue;
        cloth.v[p] += dv * dir; // Verlet too: its state is the velocity (integrate.cpp)
        ++hit;
    }
    return hit;
}

double World::kineticEnergy() const {
    double e = 0;
    for (Index p = 0; p < cloth.particleCount(); ++p) e += 0.5 * cloth.particleMass(p) * cloth.v[p].squaredNorm();
    for (const Ball& b : balls) e += 0.5 * b.mass * b.v.squaredNorm();
    return e;
}

double World::potentialEnergy() const {
    const Vec3d g(settings.gravity.x, settings.gravity.y, settings.gravity.z);
    double e = 0;
    for (Index p = 0; p < cloth.particleCount(); ++p) e -= cloth.particleMass(p) * g.dot(cloth.x[p].cast<double>());
    auto springEnergy = [&](const std::vector<Spring>& springs, float k) {
        for (const Spring& s : springs) {
            const double ext = (cloth.x[s.b] - cloth.x[s.a]).norm() - s.rest;
            e += 0.5 * k * s.weight * ext * ext;
        }
    };
    springEnergy(cloth.springs, settings.material.stretchStiffness);
    springEnergy(cloth.bends, settings.material.bendStiffness);
    return e;
}

} // namespace clothtear
