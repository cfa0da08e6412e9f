// Headless runner: load the scene, step, report.
#include <algorithm>
#include "runner.h"

#include "clothtear/params.h"
#include "clothtear/pieces.h"
#include "clothtear/scenes.h"
#include "clothtear/state_hash.h"
#include "clothtear/world_file.h"
#include "soundtrack.h"
#include "wav_file.h"

#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <optional>

namespace clothtear {
namespace {

// The torn pieces (pieces.h): how many, the rest area (m^2) and mass (kg) of the largest 32, and
// the smallest piece's area and triangle count (confetti shows there).
nlohmann::json piecesReport(const Cloth& cloth) {
    const std::vector<Piece> pieces = findPieces(cloth);
    nlohmann::json areas = nlohmann::json::array(), masses = nlohmann::json::array();
    size_t asleep = 0;
    for (const Piece& p : pieces) asleep += p.asleep;
    for (size_t k = 0; k < pieces.size() && k < 32; ++k) {
        areas.push_back(pieces[k].restArea);
        masses.push_back(pieces[k].mass);
    }
    return nlohmann::json{{"count", pieces.size()},
                          {"asleep", asleep}, // torn pieces that settled and are not simulated
                          {"areas", areas},
                          {"masses", masses},
                          {"smallest_area", pieces.empty() ? 0.0 : pieces.back().restArea},
                          {"smallest_triangles", pieces.empty() ? size_t(0) : pieces.back().triangles}};
}

} // namespace

void applyDueCuts(World& world, const std::vector<CutRequest>& cuts, size_t& next) {
    for (; next < cuts.size() && cuts[next].time <= world.time + 0.5 * world.settings.time.frameDt; ++next)
        world.cut(cuts[next].stroke); // checked when parsed: never refused here
}

nlohmann::json makeReport(const World& w, const std::string& scene, double wallSeconds) {
    using nlohmann::json;
    const Cloth& c = w.cloth;
    json phases = json::object();
    for (int p = 0; p < int(Phase::Count); ++p) {
        const double perStep = w.steps ? w.profile.ms[p] / double(w.steps) : 0.0;
        phases[phaseName(Phase(p))] = {{"ms_per_step", perStep}, {"runs", w.profile.runs[p]}};
    }
    double totalMs = 0;
    for (double ms : w.profile.ms) totalMs += ms;
    json tears = json::object();
    for (int m = 0; m < int(TearMode::Count); ++m) tears[tearModeName(TearMode(m))] = w.tearLog.counts[m];
    json warnings = json::array(); // what the user should know that is not an error
    if (const std::string warning = sceneWarnings(w); !warning.empty()) warnings.push_back(warning);
    json events = json::array();
    for (const TearEvent& e : w.tearLog.events)
        events.push_back({{"mode", tearModeName(e.mode)},
                          {"time", e.time},
                          {"rest", {e.restPos.x(), e.restPos.y(), e.restPos.z()}},
                          {"uv", {e.uv.x(), e.uv.y()}},
                          {"strain", e.strain}});
    uint64_t pinned = 0, weak = 0;
    for (uint8_t f : c.flags) pinned += (f & kPinned) != 0, weak += (f & kWeak) != 0;
    json balls = json::array();
    for (const Ball& b : w.balls)
        balls.push_back({{"x", {b.x.x(), b.x.y(), b.x.z()}}, {"v", {b.v.x(), b.v.y(), b.v.z()}}, {"radius", b.radius},
                         {"asleep", b.asleep}});
    double minY = 1e30, maxY = -1e30;
    for (const Vec3& x : c.x) minY = std::min<double>(minY, x.y()), maxY = std::max<double>(maxY, x.y());
    return json{
        {"scene", scene},
        {"seconds", w.time},
        {"steps", w.steps},
        {"substeps", w.settings.time.substeps},
        {"frame_substeps", w.frameSubsteps}, // after the stability guard (time.max_substeps)
        {"dt", double(w.settings.time.frameDt) / std::max(1, w.frameSubsteps > 0 ? w.frameSubsteps : w.settings.time.substeps)},
        {"guard_capped_springs", w.guardCappedSprings}, // springs the guard softened (last frame)
        {"guard_stiffness_kept", w.guardStiffnessKept}, // smallest fraction of the set stiffness kept
        {"guard_damping_kept", w.guardDampingKept},     // and of the set damping
        {"integrator", formatParamValue(w.settings, *findParam("time.integrator"))},
        {"particles", c.particleCount()},
        {"pinned", pinned},
        {"weak_points", weak},
        {"springs", c.springs.size()},
        {"bend_springs", c.bends.size()},
        {"triangles", c.triangles.size()},
        {"total_mass", c.totalMass()},
        {"rest_area", c.totalRestArea()},
        {"uv_area", c.totalUvArea()},
        {"max_strain", w.maxStrain},
        {"min_y", minY},
        {"max_y", maxY},
        {"kinetic_energy", w.kineticEnergy()},
        {"finite", w.finite},
        {"state_hash", hashHex(stateHash(w))}, // bit-identical runs give the same hash (state_hash.h)
        {"non_finite_where", w.nonFiniteWhere},
        {"ms_per_step", w.steps ? totalMs / double(w.steps) : 0.0},
        {"wall_seconds", wallSeconds},
        {"phases", phases},
        // Sub-steps whose length limit was still correcting at its last pass, and those springs.
        {"limit_capped_substeps", w.profile.limitCapped},
        {"limit_capped_springs", w.profile.limitCappedSprings},
        {"substeps_run", w.profile.substeps},
        // of them with the springs' damping taken implicitly (time.damping), and the last frame's way
        {"damping_implicit_substeps", w.profile.dampingImplicitSubsteps},
        {"damping_implicit", w.profile.dampingImplicit},
        {"limit_passes", w.profile.limitPasses}, // passes of the length limit, summed over sub-steps
        {"limit_region_passes", w.profile.limitRegionPasses}, // of them split over the threads by region
        // sub-steps whose limit skipped the tethers / the listing after them (exact skips, limit.cpp)
        {"limit_tethers_skipped", w.profile.limitTethersSkipped},
        {"limit_expand_skipped", w.profile.limitExpandSkipped},
        {"limit_listings_avx2", w.profile.limitListingsAvx2},
        {"spring_kernel", w.profile.springKernel}, // the spring groups' kernel (avx2, sse2, generic)
        {"grouped_springs", w.profile.groupedSprings}, // springs it ran in the last spring phase
        {"merged_springs", w.profile.mergedSprings},   // bend-shear springs computed in a twin's entry
        {"tears", tears},
        {"tears_total", w.tearLog.total()}, // every event, the knife's cut springs included ("tears" by mode)
        {"knife", {{"cuts", w.tearLog.knifeCuts}, {"springs", w.tearLog.counts[int(TearMode::Knife)]}}},
        {"pieces", piecesReport(c)},
        {"tear_events", events},
        {"warnings", warnings},
        {"validation_error", w.tearLog.validationError}, // first invariant violation (tear.validate=1)
        {"balls", balls},
    };
}

std::string loadWorldFile(World& world, const std::string& path, std::span<const std::string> overrides) {
    Result<World> loaded = loadWorld(path);
    if (!loaded.ok()) return loaded.error;
    for (const std::string& o : overrides)
        if (std::string err = applyAssignment(loaded.value.settings, o); !err.empty()) return "--set " + o + ": " + err;
    world = std::move(loaded.value);
    return {};
}

nlohmann::json loadedReport(const std::string& path, const World& w) {
    return {{"file", path},
            {"format_version", kWorldFileVersion},
            {"seconds", w.time},
            {"steps", w.steps},
            {"particles", w.cloth.particleCount()},
            {"tears_total", w.tearLog.total()},
            {"asleep", w.asleep},
            {"state_hash", hashHex(stateHash(w))}};
}

int runHeadless(const RunOptions& o) {
    World world;
    // From a world file, the report's scene is "load:FILE" and its "loaded" field says where the
    // world stood; --seconds then runs that much further.
    const std::string scene = o.load.empty() ? o.scene : "load:" + o.load;
    nlohmann::json loaded;
    const std::string err = o.load.empty() ? loadScene(world, o.scene, o.sets) : loadWorldFile(world, o.load, o.sets);
    if (!err.empty()) {
        std::cerr << "clothtear: " << err << "\n";
        return 2;
    }
    if (!o.load.empty()) loaded = loadedReport(o.load, world);
    if (const std::string warning = sceneWarnings(world); !warning.empty())
        std::cerr << "clothtear: warning: " << warning << "\n";
    const long frames = std::lround(o.seconds / world.settings.time.frameDt);
    std::optional<audio::Soundtrack> sound; // --audio-out: the tears' sound, frame by frame
    if (!o.audioOut.empty()) sound.emplace(world);
    const auto start = std::chrono::steady_clock::now();
    size_t nextCut = 0;
    for (long f = 0; f < frames; ++f) {
        applyDueCuts(world, o.cuts, nextCut);
        world.step();
        if (sound) sound->afterFrame(world);
    }
    applyDueCuts(world, o.cuts, nextCut); // a cut at the run's very end
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    nlohmann::json report = makeReport(world, scene, wall);
    if (!loaded.is_null()) report["loaded"] = loaded;
    if (sound) {
        if (const std::string err = audio::writeWav(o.audioOut, sound->samples(), 2, sound->sampleRate()); !err.empty()) {
            std::cerr << "clothtear: --audio-out: " << err << "\n";
            return 2;
        }
        report["audio"] = {{"file", o.audioOut},
                           {"seconds", double(sound->frames()) / sound->sampleRate()},
                           {"samples", sound->frames()}, // stereo frames
                           {"sample_rate", sound->sampleRate()},
                           {"grains", sound->synth().grains()}};
    }
    if (!o.exportObj.empty() && !saveObj(clothMesh(world.cloth), o.exportObj)) {
        std::cerr << "clothtear: cannot write the OBJ export to '" << o.exportObj << "'\n";
        return 2;
    }
    if (!o.save.empty())
        if (std::string saveErr = saveWorld(world, o.save); !saveErr.empty()) {
            std::cerr << "clothtear: " << saveErr << "\n";
            return 2;
        }
    if (o.json == "-") {
        std::cout << report.dump(2) << "\n";
    } else if (!o.json.empty()) {
        std::ofstream out(o.json);
        if (!out) {
            std::cerr << "clothtear: cannot write report to '" << o.json << "'\n";
            return 2;
        }
        out << report.dump(2) << "\n";
    } else {
        std::cout << scene << ": " << world.steps << " frames, " << world.cloth.particleCount() << " particles, "
                  << world.cloth.triangles.size() << " triangles, max strain " << world.maxStrain << ", tears "
                  << world.tearLog.total() << ", " << report["ms_per_step"].get<double>() << " ms/frame, "
                  << (world.finite ? "finite" : "NON-FINITE");
        if (sound) std::cout << ", audio " << o.audioOut << " (" << double(sound->frames()) / sound->sampleRate() << " s)";
        std::cout << "\n";
    }
    return world.finite ? 0 : 1;
}

} // namespace clothtear
