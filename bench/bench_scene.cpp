#include "bench_scene.h"

#include "clothtear/scenes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <mutex>
#include <stdexcept>
#include <vector>

namespace clothtear::bench {

StabilityReport stability(const World& world) {
    const Cloth& c = world.cloth;
    const double dt = double(world.settings.time.frameDt) / world.settings.time.substeps;
    std::vector<double> k, kd;
    springSumsPerParticle(c, world.settings, k, kd);
    StabilityReport r;
    for (Index p = 0; p < c.particleCount(); ++p) {
        if (c.invMass[p] == 0.f) continue;
        const double mass = c.particleMass(p);
        r.stiffnessTerm = std::max(r.stiffnessTerm, dt * dt * k[p] / mass);
        r.dampingTerm = std::max(r.dampingTerm, dt * kd[p] / mass);
    }
    return r;
}

float maxStructuralStrain(const World& world) {
    float worst = 0.f;
    for (const Spring& s : world.cloth.springs)
        worst = std::max(worst, (world.cloth.x[s.b] - world.cloth.x[s.a]).norm() / s.rest - 1.f);
    return worst;
}

std::string describeMaterial(const World& w) {
    const MaterialSettings& m = w.settings.material;
    const StabilityReport r = stability(w);
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "stretch_stiffness=%.4g stretch_damping=%.4g bend_stiffness=%.4g bend_damping=%.4g "
                  "(requested a/2+b=%.3f, sqrt(a)=%.3f; guard %s)",
                  m.stretchStiffness, m.stretchDamping, m.bendStiffness, m.bendDamping, r.margin(),
                  std::sqrt(r.stiffnessTerm), w.settings.time.stabilityGuard ? "on" : "off");
    return buf;
}

World settledCurtain(const CurtainOptions& o) {
    static std::mutex mutex;
    static std::map<std::pair<int, double>, World> cache;
    std::lock_guard<std::mutex> lock(mutex);
    auto key = std::make_pair(o.resolution, o.settleSeconds);
    auto it = cache.find(key);
    if (it == cache.end()) {
        const std::string r = std::to_string(o.resolution);
        // Sleep off: these cases time the simulation of a cloth at rest, which would otherwise sleep.
        const std::vector<std::string> overrides = {"cloth.resolution_x=" + r, "cloth.resolution_y=" + r,
                                                    "sleep.enabled=false"};
        World w;
        if (std::string err = loadScene(w, "curtain", overrides); !err.empty()) throw std::runtime_error(err);
        const int frames = int(std::lround(o.settleSeconds / w.settings.time.frameDt));
        for (int f = 0; f < frames; ++f) w.step();
        if (!w.finite) throw std::runtime_error("curtain " + r + " blew up while settling: " + w.nonFiniteWhere);
        // World::substep() then takes the sub-step World::step() takes at this resolution (the
        // stability guard's count for the material's stable step), not 1/600 s with capped springs.
        w.settings.time.substeps = std::max(w.settings.time.substeps, w.frameSubsteps);
        it = cache.emplace(key, std::move(w)).first;
    }
    World w = it->second;
    w.settings.tear.enabled = o.tearing;
    w.profile.reset();
    return w;
}

} // namespace clothtear::bench
