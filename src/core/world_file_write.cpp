// Writing a world file (world_file.h; layout in world_file_format.h and docs/world-file.md).
#include "clothtear/params.h"
#include "clothtear/world_file.h"

#include "step/implicit_euler.h"
#include "step/step_state.h"
#include "world_file_format.h"

#include <bit>
#include <cerrno>
#include <cstdio>
#include <cstring>

namespace clothtear {
namespace {

using namespace worldfile;

// Little-endian bytes, whatever the machine: a file written on one machine loads on any other.
class ByteWriter {
  public:
    std::string out;
    void u8(uint8_t v) { out.push_back(char(v)); }
    void u16(uint16_t v) { u8(uint8_t(v & 0xff)), u8(uint8_t(v >> 8)); }
    void u32(uint32_t v) {
        for (int i = 0; i < 4; ++i) out.push_back(char((v >> (8 * i)) & 0xff));
    }
    void u64(uint64_t v) {
        for (int i = 0; i < 8; ++i) out.push_back(char((v >> (8 * i)) & 0xff));
    }
    void f32(float v) { u32(std::bit_cast<uint32_t>(v)); }
    void f64(double v) { u64(std::bit_cast<uint64_t>(v)); }
    void vec(const Vec3& v) { f32(v.x()), f32(v.y()), f32(v.z()); }
    void vec(const Vec3d& v) { f64(v.x()), f64(v.y()), f64(v.z()); }
    void vec(const Vec2d& v) { f64(v.x()), f64(v.y()); }
    void spring(const Spring& s) { u32(s.a), u32(s.b), f32(s.rest), f32(s.weight); }
    void text(const std::string& s) {
        u32(uint32_t(s.size()));
        out += s;
    }
    // A section: its tag, then its body's length, filled in by endSection.
    void beginSection(SectionId id) {
        out.append(kSections[id].tag, 4);
        lengthAt_ = out.size();
        u64(0);
    }
    void endSection() {
        const uint64_t length = out.size() - lengthAt_ - 8;
        for (int i = 0; i < 8; ++i) out[lengthAt_ + i] = char((length >> (8 * i)) & 0xff);
    }

  private:
    size_t lengthAt_ = 0;
};

// Every parameter as "name=value", in the form --set reads (the reader applies them through the
// same table, with the same checks).
void writeSettings(ByteWriter& w, const Settings& settings) {
    const auto params = allParams();
    w.u32(uint32_t(params.size()));
    for (const ParamInfo& p : params) w.text(std::string(p.name) + "=" + formatParamValue(settings, p));
}

void writeMesh(ByteWriter& w, const MeshData& mesh) {
    w.u64(mesh.positions.size());
    for (const Vec3d& p : mesh.positions) w.vec(p);
    w.u64(mesh.triangles.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        for (Index v : mesh.triangles[t]) w.u32(v);
        for (const Vec2d& uv : mesh.cornerUVs[t]) w.vec(uv);
    }
}

// The inverse masses are not written: they follow from the flags, the density and the area shares
// (Cloth::refreshInvMass), and the reader recomputes them.
void writeCloth(ByteWriter& w, const Cloth& c) {
    w.beginSection(kSecCloth);
    w.u64(c.topologyRevision);
    w.f32(c.density);
    w.f32(c.minSplitRest);
    w.endSection();

    w.beginSection(kSecParticles);
    w.u64(c.particleCount());
    for (Index p = 0; p < c.particleCount(); ++p) {
        w.vec(c.x[p]);
        w.vec(c.v[p]);
        w.f64(c.areaShare[p]);
        w.vec(c.rest[p]);
        w.u8(c.flags[p]);
        w.u32(uint32_t(c.particleTris[p].size()));
        for (Index t : c.particleTris[p]) w.u32(t);
    }
    w.endSection();

    w.beginSection(kSecSprings);
    w.u64(c.springs.size());
    for (size_t s = 0; s < c.springs.size(); ++s) {
        w.spring(c.springs[s]);
        w.u32(c.springTopo[s].tri[0]), w.u32(c.springTopo[s].tri[1]), w.u32(c.springTopo[s].bend);
    }
    w.endSection();

    w.beginSection(kSecBends);
    w.u64(c.bends.size());
    for (size_t b = 0; b < c.bends.size(); ++b) w.spring(c.bends[b]), w.u32(c.bendEdge[b]);
    // Version 3: the kes hinges' memory, none or one per bend.
    w.u64(c.bendMemory.size());
    for (const BendMemory& m : c.bendMemory)
        w.f32(m.extremeK), w.f32(m.reversalK), w.f32(m.reversalM), w.u32(uint32_t(m.direction));
    w.endSection();

    w.beginSection(kSecTriangles);
    w.u64(c.triangles.size());
    for (const Triangle& t : c.triangles) {
        for (Index p : t.p) w.u32(p);
        for (Index s : t.s) w.u32(s);
        for (const Vec2d& uv : t.uv) w.vec(uv);
        w.f64(t.restArea);
    }
    w.endSection();
}

void writeBodies(ByteWriter& w, const World& world) {
    w.beginSection(kSecBalls);
    w.u64(world.balls.size());
    for (const Ball& b : world.balls) w.vec(b.x), w.vec(b.v), w.f32(b.radius), w.f32(b.mass);
    w.endSection();

    w.beginSection(kSecDrivers);
    w.u64(world.drivers.size());
    for (const Driver& d : world.drivers) {
        w.vec(d.velocity);
        w.u64(d.particles.size());
        for (Index p : d.particles) w.u32(p);
    }
    w.endSection();
}

// Time, counters, and the last frame's figures (so a report of the loaded world reads as the saved one's).
void writeWorldScalars(ByteWriter& w, const World& world) {
    w.beginSection(kSecWorld);
    w.f64(world.time);
    w.u64(world.steps);
    w.u64(world.sleptFrames);
    w.u8(world.asleep ? 1 : 0);
    static_assert(int(TearMode::Count) == 4, "a tear mode more is a new file version");
    for (uint64_t n : world.tearLog.counts) w.u64(n);
    w.u64(world.tearLog.knifeCuts);
    w.f32(world.maxStrain);
    w.f32(world.maxSpeed);
    w.u32(uint32_t(world.frameSubsteps));
    w.u64(world.guardCappedSprings);
    w.f32(world.guardStiffnessKept);
    w.f32(world.guardDampingKept);
    w.endSection();
}

// What the step carries from one frame to the next beyond the cloth (step_state.h): Verlet's half
// kicks, the sleep state, and implicit Euler's last dv (its next solve starts from it). The caches
// are not written: built from the cloth and the settings, they come out the same.
void writeStepState(ByteWriter& w, const World& world) {
    const StepState& s = world.stepState();
    w.beginSection(kSecStep);
    w.u8(s.verletRunning ? 1 : 0);
    w.u64(s.verletKick.size());
    for (const Vec3& k : s.verletKick) w.vec(k);
    const SleepState& sleep = s.sleep;
    w.f64(sleep.restSince);
    w.vec(sleep.lo);
    w.vec(sleep.hi);
    w.u64(sleep.topology);
    // The mass revision is unique per process: what matters is whether the cloth still has the one
    // it fell asleep with.
    w.u8(sleep.mass == world.cloth.massRevision ? 1 : 0);
    // The parameters it fell asleep with, compared at every frame while asleep (sleep.cpp); only then.
    if (world.asleep) writeSettings(w, sleep.settings);
    else w.u32(0);
    const ImplicitCacheSlot& slot = s.implicit;
    // (A cache restored from a file has its dv but no matrix yet: built is false, the dv counts.)
    const bool warm = slot.cache && slot.stamp.valid &&
                      slot.stamp.built.topology == world.cloth.topologyRevision &&
                      slot.stamp.built.mass == world.cloth.massRevision;
    const Eigen::VectorXd none;
    const Eigen::VectorXd& dv = warm ? slot.cache->dv : none;
    w.u64(uint64_t(dv.size()));
    for (Eigen::Index i = 0; i < dv.size(); ++i) w.f64(dv[i]);
    // Torn pieces (piece_sleep.cpp): frames each particle has been still; particles added since the
    // last frame (a knife cut) have 0, as the next frame gives them.
    const size_t n = world.cloth.particleCount();
    w.u64(sleep.stillFrames.empty() ? 0 : n);
    if (!sleep.stillFrames.empty())
        for (size_t p = 0; p < n; ++p) w.u16(p < sleep.stillFrames.size() ? sleep.stillFrames[p] : 0);
    // Balls (ball_sleep.cpp): frames each has been still, and whether it sleeps.
    w.u64(world.balls.size());
    for (const Ball& b : world.balls) w.u16(b.stillFrames), w.u8(b.asleep ? 1 : 0);
    w.endSection();
}

} // namespace

std::string serializeWorld(const World& world, std::string& bytes) {
    if (!world.finite) return "the world is not finite (" + world.nonFiniteWhere + "); nothing to save";
    ByteWriter w;
    w.out.append(kMagic);
    w.u32(kWorldFileVersion);
    w.beginSection(kSecSettings);
    writeSettings(w, world.settings);
    w.endSection();
    w.beginSection(kSecMesh);
    writeMesh(w, world.restMesh);
    w.endSection();
    writeCloth(w, world.cloth);
    writeBodies(w, world);
    writeWorldScalars(w, world);
    writeStepState(w, world);
    bytes = std::move(w.out);
    return {};
}

std::string saveWorld(const World& world, const std::string& path) {
    std::string bytes;
    try {
        if (std::string err = serializeWorld(world, bytes); !err.empty()) return path + ": cannot save: " + err;
        // What the reader refuses (a parameter a test or scene set outside its valid range, a cloth
        // flown beyond +-1e5 m) is not written: a saved file always loads.
        if (const Result<World> back = parseWorld(bytes, path); !back.ok())
            return path + ": cannot save: the file would not load again: " + back.error.substr(path.size() + 2);
    } catch (const std::bad_alloc&) {
        return path + ": cannot save: out of memory";
    }
    errno = 0;
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) return path + ": cannot write: " + (errno ? std::strerror(errno) : "unknown error");
    bool ok = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
    ok = (std::fclose(file) == 0) && ok;
    if (!ok) {
        std::remove(path.c_str());
        return path + ": cannot write (disk full?); nothing saved";
    }
    return {};
}

} // namespace clothtear
