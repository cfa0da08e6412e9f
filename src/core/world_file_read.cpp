// Reading a world file (world_file.h; layout in world_file_format.h and docs/world-file.md).
//
// Whatever the bytes, the reader answers with a World or one line: the file, the byte offset and
// section, and what is wrong there. Every count is checked against the bytes left in its section
// before anything is allocated (a count of 4e9 particles in a 100-byte file allocates nothing), every
// float is checked to be finite and within what the float state can hold, every index the step
// follows without a check is checked here, and the cloth then has to pass validateCloth.
#include "clothtear/knife.h"
#include "clothtear/params.h"
#include "clothtear/tear.h"
#include "clothtear/world_file.h"

#include "file_read.h"
#include "step/implicit_euler.h"
#include "step/revisions.h"
#include "step/step_state.h"
#include "world_file_format.h"

#include <bit>
#include <cmath>
#include <vector>

namespace clothtear {
namespace {

using namespace worldfile;

// Where and what; turned into the one-line message by parseWorld. Thrown only inside this file.
struct FormatError {
    size_t offset;
    const char* section;
    std::string what;
};

// Positions and speeds a world file holds: beyond them the float state loses the centimetre
// (positions, as mesh.h's kMaxCoordinate) or a frame's motion leaves that range at once (speeds).
constexpr double kMaxSpeed = 1e5; // m/s

class ByteReader {
  public:
    explicit ByteReader(std::string_view bytes) : b_(bytes), end_(bytes.size()) {}
    size_t offset() const { return pos_; }
    size_t left() const { return end_ - pos_; }

    [[noreturn]] void fail(const std::string& what) const { throw FormatError{last_, section_, what}; }
    [[noreturn]] void failAt(size_t offset, const std::string& what) const { throw FormatError{offset, section_, what}; }

    uint8_t u8() { return uint8_t(take(1)[0]); }
    uint16_t u16() { return uint16_t(le(take(2))); }
    uint32_t u32() { return uint32_t(le(take(4))); }
    uint64_t u64() { return le(take(8)); }
    float f32() { return std::bit_cast<float>(u32()); }
    double f64() { return std::bit_cast<double>(u64()); }
    template <class V> V vec() { // Vec3, Vec3d, Vec2d; an error then points at its first component
        const size_t at = pos_;
        V v;
        for (int i = 0; i < v.size(); ++i) v[i] = sizeof(typename V::Scalar) == 4 ? f32() : f64();
        last_ = at;
        return v;
    }
    std::string_view bytes(size_t n) { return take(n); }

    // A section header: the expected tag, and a length the file has.
    void beginSection(SectionId id) {
        section_ = kSections[id].name;
        last_ = pos_;
        if (left() < kSectionHeaderBytes)
            fail(left() == 0 ? "the file ends before this section (truncated)" : "the file ends inside the section header (truncated)");
        const std::string_view tag = take(4);
        if (tag != std::string_view(kSections[id].tag, 4))
            failAt(pos_ - 4, "expected the tag '" + std::string(kSections[id].tag) + "', found '" + shownInMessage(tag) + "'");
        const uint64_t length = u64();
        if (length > left())
            fail("the section says it has " + std::to_string(length) + " bytes, the file has " + std::to_string(left()) +
                 " after its header (truncated)");
        end_ = pos_ + length;
    }
    void endSection() {
        last_ = pos_;
        if (pos_ != end_) fail(std::to_string(end_ - pos_) + " bytes left over after the section's last field");
        end_ = b_.size();
    }
    // A count of records of at least `bytes` each: refused when they cannot fit in what is left of the
    // section, so that a lying count allocates nothing.
    size_t count(uint64_t n, size_t bytes, const char* what) {
        if (n >= kNone || n > left() / bytes)
            fail(std::string(what) + " count " + std::to_string(n) + " needs at least " + std::to_string(n) + " x " +
                 std::to_string(bytes) + " bytes; the section has " + std::to_string(left()) + " left");
        return size_t(n);
    }

  private:
    std::string_view take(size_t n) {
        last_ = pos_;
        if (n > left())
            fail("the section ends " + std::to_string(n - left()) + " bytes before the field it is reading (its counts or length are wrong)");
        const std::string_view v = b_.substr(pos_, n);
        pos_ += n;
        return v;
    }
    static uint64_t le(std::string_view v) {
        uint64_t x = 0;
        for (size_t i = 0; i < v.size(); ++i) x |= uint64_t(uint8_t(v[i])) << (8 * i);
        return x;
    }

    std::string_view b_;
    size_t pos_ = 0, end_ = 0, last_ = 0;
    const char* section_ = "header";
};

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}
template <class V> std::string show(const V& v) {
    std::string s = "(";
    for (int i = 0; i < v.size(); ++i) s += (i ? ", " : "") + num(double(v[i]));
    return s + ")";
}

// Checks on what was just read (the reader's last field).
template <class V> void requireFinite(ByteReader& r, const V& v, double limit, const std::string& what) {
    if (!v.allFinite()) r.fail(what + " is not finite " + show(v));
    if (double(v.cwiseAbs().maxCoeff()) > limit) r.fail(what + " " + show(v) + " is beyond +-" + num(limit));
}
// A vector read and checked: finite, each component within +-limit.
template <class V> V boundedVec(ByteReader& r, double limit, const std::string& what) {
    const V v = r.vec<V>();
    requireFinite(r, v, limit, what);
    return v;
}
void requireNumber(ByteReader& r, double v, double lo, double hi, const std::string& what) {
    if (!(v >= lo && v <= hi)) r.fail(what + " " + num(v) + " is not in [" + num(lo) + ", " + num(hi) + "]");
}
void requirePositive(ByteReader& r, double v, double hi, const std::string& what) {
    if (!(v > 0 && v <= hi)) r.fail(what + " " + num(v) + " is not in (0, " + num(hi) + "]");
}
// Longest distance between two points within +-kMaxCoordinate.
constexpr double kMaxLength = 4 * kMaxCoordinate;

// "name=value" lines through the parameter table, as --set reads them: an unknown name, a bad
// value or one outside its valid range is refused with the table's own message. A parameter the
// file does not name keeps its default (a parameter added after the file was written).
void readSettings(ByteReader& r, Settings& settings) {
    const size_t n = r.count(r.u32(), 4, "parameter");
    const auto params = allParams();
    std::vector<bool> seen(params.size(), false);
    for (size_t i = 0; i < n; ++i) {
        const uint32_t length = r.u32();
        if (length > kMaxSettingBytes) r.fail("parameter line " + std::to_string(i) + " is " + std::to_string(length) + " bytes long");
        const size_t at = r.offset();
        const std::string_view line = r.bytes(length);
        if (const ParamInfo* p = findParam(line.substr(0, line.find('='))); p) {
            if (seen[size_t(p - params.data())]) r.failAt(at, std::string("parameter '") + p->name + "' appears twice");
            seen[size_t(p - params.data())] = true;
        }
        if (std::string err = applyAssignment(settings, line); !err.empty()) r.failAt(at, err);
    }
}

MeshData readMesh(ByteReader& r) {
    MeshData mesh;
    mesh.positions.resize(r.count(r.u64(), kMeshVertexBytes, "vertex"));
    for (Vec3d& p : mesh.positions) p = r.vec<Vec3d>();
    const size_t nt = r.count(r.u64(), kMeshTriangleBytes, "triangle");
    mesh.triangles.resize(nt);
    mesh.cornerUVs.resize(nt);
    for (size_t t = 0; t < nt; ++t) {
        for (Index& v : mesh.triangles[t]) v = r.u32();
        for (Vec2d& uv : mesh.cornerUVs[t]) uv = r.vec<Vec2d>();
    }
    // The net every mesh source goes through (indices, finite and bounded coordinates, no degenerate
    // triangle): World::rebuild builds from it.
    if (!mesh.triangles.empty() || !mesh.positions.empty())
        if (std::string err = checkMesh(mesh, "the rest mesh"); !err.empty()) r.fail(err);
    return mesh;
}

void readParticles(ByteReader& r, Cloth& c) {
    const size_t n = r.count(r.u64(), kParticleBytes, "particle");
    c.x.resize(n), c.v.resize(n), c.invMass.assign(n, 0.f), c.areaShare.resize(n), c.rest.resize(n);
    c.flags.resize(n), c.particleTris.resize(n);
    // kTouched lives within one sub-step (the collide phase sets it, the contact phase clears it),
    // so a world between steps, the only one ever saved, never holds it; the limit's listing reads
    // it from a table built from the sub-step's contacts, and a stale mark would disagree with it.
    constexpr uint8_t kKnownFlags = kPinned | kWeak | kHinge | kHem | kAsleep;
    for (size_t p = 0; p < n; ++p) {
        const std::string at = "particle " + std::to_string(p) + ": ";
        c.x[p] = boundedVec<Vec3>(r, kMaxCoordinate, at + "position");
        c.v[p] = boundedVec<Vec3>(r, kMaxSpeed, at + "velocity");
        c.areaShare[p] = r.f64();
        requireNumber(r, c.areaShare[p], 0.0, 1e300, at + "area share");
        c.rest[p] = boundedVec<Vec3d>(r, kMaxCoordinate, at + "rest position");
        c.flags[p] = r.u8();
        if (c.flags[p] & kTouched)
            r.fail(at + "flag bit " + std::to_string(kTouched) +
                   " (under a ball) is set; it lives within one sub-step and a saved world never holds it");
        if (c.flags[p] & ~kKnownFlags) r.fail(at + "unknown flag bits " + std::to_string(c.flags[p] & ~kKnownFlags));
        c.particleTris[p].resize(r.count(r.u32(), 4, (at + "triangle").c_str()));
        for (Index& t : c.particleTris[p]) t = r.u32();
    }
}

// Springs, bend-shear springs, triangles: the indices are checked by validateCloth, in one place,
// after everything was read (it checks every range before it follows an index).

// A Spring record: ends, rest length (m), weight. A bend-shear spring across a flat pair of
// triangles may have a rest length of 0 (the opposite corners on one point); a structural one not.
Spring readSpring(ByteReader& r, const std::string& at, bool restMayBeZero) {
    Spring sp;
    sp.a = r.u32(), sp.b = r.u32();
    sp.rest = r.f32();
    if (restMayBeZero) requireNumber(r, sp.rest, 0.0, kMaxLength, at + "rest length");
    else requirePositive(r, sp.rest, kMaxLength, at + "rest length");
    sp.weight = r.f32();
    requireNumber(r, sp.weight, 0.0, 1e30, at + "weight");
    return sp;
}

void readSprings(ByteReader& r, Cloth& c) {
    const size_t ns = r.count(r.u64(), kSpringBytes, "spring");
    c.springs.resize(ns), c.springTopo.resize(ns);
    for (size_t s = 0; s < ns; ++s) {
        c.springs[s] = readSpring(r, "spring " + std::to_string(s) + ": ", false);
        for (Index& t : c.springTopo[s].tri) t = r.u32();
        c.springTopo[s].bend = r.u32();
    }
}

void readBends(ByteReader& r, Cloth& c, uint32_t version) {
    const size_t nb = r.count(r.u64(), kBendBytes, "bend spring");
    c.bends.resize(nb), c.bendEdge.resize(nb);
    for (size_t b = 0; b < nb; ++b) {
        c.bends[b] = readSpring(r, "bend spring " + std::to_string(b) + ": ", true);
        c.bendEdge[b] = r.u32();
    }
    if (version < 3) return; // no hinge memory before version 3
    const size_t nm = r.count(r.u64(), kBendMemoryBytes, "bend memory");
    if (nm != 0 && nm != nb)
        r.fail(std::to_string(nm) + " hinge memories for " + std::to_string(nb) + " bend springs (none or one each)");
    c.bendMemory.resize(nm);
    for (size_t b = 0; b < nm; ++b) {
        const std::string at = "bend memory " + std::to_string(b) + ": ";
        BendMemory& m = c.bendMemory[b];
        m.extremeK = r.f32();
        requireNumber(r, m.extremeK, -1e30, 1e30, at + "extreme curvature");
        m.reversalK = r.f32();
        requireNumber(r, m.reversalK, -1e30, 1e30, at + "reversal curvature");
        m.reversalM = r.f32();
        requireNumber(r, m.reversalM, -1e30, 1e30, at + "reversal moment");
        m.direction = int32_t(r.u32());
        if (m.direction < -1 || m.direction > 1) r.fail(at + "direction " + std::to_string(m.direction) + " (not -1, 0 or 1)");
    }
}

void readTriangles(ByteReader& r, Cloth& c) {
    const size_t nt = r.count(r.u64(), kTriangleBytes, "triangle");
    c.triangles.resize(nt);
    for (size_t t = 0; t < nt; ++t) {
        const std::string at = "triangle " + std::to_string(t) + ": ";
        Triangle& tri = c.triangles[t];
        for (Index& p : tri.p) p = r.u32();
        for (Index& s : tri.s) s = r.u32();
        for (Vec2d& uv : tri.uv) uv = boundedVec<Vec2d>(r, kMaxUv, at + "texture coordinate");
        tri.restArea = r.f64();
        requirePositive(r, tri.restArea, kMaxLength * kMaxLength, at + "rest area");
    }
}

void readCloth(ByteReader& r, Cloth& c, uint32_t version) {
    r.beginSection(kSecCloth);
    c.topologyRevision = r.u64();
    c.density = r.f32();
    const ParamInfo& density = *findParam("material.density");
    requireNumber(r, c.density, density.hardMin, density.hardMax, "density");
    c.minSplitRest = r.f32();
    requireNumber(r, c.minSplitRest, 0.0, kMaxLength, "shortest spring a tear halves");
    r.endSection();
    r.beginSection(kSecParticles);
    readParticles(r, c);
    r.endSection();
    r.beginSection(kSecSprings);
    readSprings(r, c);
    r.endSection();
    r.beginSection(kSecBends);
    readBends(r, c, version);
    r.endSection();
    r.beginSection(kSecTriangles);
    readTriangles(r, c);
    r.endSection();
}

void readBodies(ByteReader& r, World& w) {
    r.beginSection(kSecBalls);
    w.balls.resize(r.count(r.u64(), kBallBytes, "ball"));
    for (size_t i = 0; i < w.balls.size(); ++i) {
        const std::string at = "ball " + std::to_string(i) + ": ";
        Ball& b = w.balls[i];
        b.x = boundedVec<Vec3>(r, kMaxCoordinate, at + "position");
        b.v = boundedVec<Vec3>(r, kMaxSpeed, at + "velocity");
        b.radius = r.f32();
        requirePositive(r, b.radius, kMaxCoordinate, at + "radius");
        b.mass = r.f32();
        requireNumber(r, b.mass, 0.0, 1e12, at + "mass");
    }
    r.endSection();

    r.beginSection(kSecDrivers);
    w.drivers.resize(r.count(r.u64(), kDriverBytes, "driver"));
    for (size_t i = 0; i < w.drivers.size(); ++i) {
        const std::string at = "driver " + std::to_string(i) + ": ";
        Driver& d = w.drivers[i];
        d.velocity = boundedVec<Vec3>(r, kMaxSpeed, at + "velocity");
        d.particles.resize(r.count(r.u64(), 4, (at + "particle").c_str()));
        for (Index& p : d.particles) {
            p = r.u32();
            if (p >= w.cloth.particleCount())
                r.fail(at + "particle " + std::to_string(p) + " does not exist (" +
                       std::to_string(w.cloth.particleCount()) + " particles)");
        }
    }
    r.endSection();
}

void readWorldScalars(ByteReader& r, World& w) {
    r.beginSection(kSecWorld);
    w.time = r.f64();
    requireNumber(r, w.time, 0.0, 1e15, "time");
    w.steps = r.u64();
    w.sleptFrames = r.u64();
    const uint8_t asleep = r.u8();
    if (asleep > 1) r.fail("asleep is " + std::to_string(asleep) + ", not 0 or 1");
    w.asleep = asleep == 1;
    for (uint64_t& n : w.tearLog.counts) n = r.u64();
    w.tearLog.knifeCuts = r.u64();
    w.maxStrain = r.f32();
    requireNumber(r, w.maxStrain, -1.0, 1e30, "largest strain of the last frame");
    w.maxSpeed = r.f32();
    requireNumber(r, w.maxSpeed, 0.0, 1e30, "largest speed of the last frame");
    w.frameSubsteps = int(r.u32());
    requireNumber(r, w.frameSubsteps, 0, 1e9, "sub-steps of the last frame");
    w.guardCappedSprings = r.u64();
    w.guardStiffnessKept = r.f32();
    requireNumber(r, w.guardStiffnessKept, 0.0, 1.0, "stiffness the guard kept");
    w.guardDampingKept = r.f32();
    requireNumber(r, w.guardDampingKept, 0.0, 1.0, "damping the guard kept");
    r.endSection();
}

// The step's state that outlives a frame (world_file_write.cpp, writeStepState), back into a fresh
// StepState whose caches the first step rebuilds.
void readStepState(ByteReader& r, World& w, StepState& s, uint32_t version) {
    r.beginSection(kSecStep);
    const Cloth& c = w.cloth;
    const uint8_t verlet = r.u8();
    if (verlet > 1) r.fail("Verlet running is " + std::to_string(verlet) + ", not 0 or 1");
    s.verletRunning = verlet == 1;
    const uint64_t kicks = r.u64();
    if (kicks > c.particleCount()) r.fail("Verlet kicks for " + std::to_string(kicks) + " particles, the cloth has " + std::to_string(c.particleCount()));
    s.verletKick.resize(r.count(kicks, 12, "Verlet kick"));
    for (Vec3& k : s.verletKick) k = boundedVec<Vec3>(r, kMaxSpeed, "Verlet kick");
    SleepState& sleep = s.sleep;
    sleep.restSince = r.f64();
    if (sleep.restSince != -1.0) requireNumber(r, sleep.restSince, 0.0, w.time, "at rest since");
    sleep.lo = boundedVec<Vec3>(r, 1e30, "sleep box corner");
    sleep.hi = boundedVec<Vec3>(r, 1e30, "sleep box corner");
    sleep.topology = r.u64();
    const uint8_t sameMass = r.u8();
    if (sameMass > 1) r.fail("sleep mass flag is " + std::to_string(sameMass) + ", not 0 or 1");
    // Not asleep on this cloth's masses: any value the cloth cannot have (revisions start at 1).
    sleep.mass = sameMass ? c.massRevision : 0;
    const size_t snapshotAt = r.offset();
    readSettings(r, sleep.settings);
    if (w.asleep && r.offset() == snapshotAt + 4)
        r.failAt(snapshotAt, "the cloth is asleep but the parameters it fell asleep with are missing");
    sleep.pieceSettings = w.settings;
    const uint64_t unknowns = r.u64();
    if (unknowns > 0) {
        size_t free = 0;
        for (float m : c.invMass) free += m > 0.f ? 1 : 0;
        if (unknowns != 3 * free)
            r.fail("implicit Euler's last dv has " + std::to_string(unknowns) + " values; the cloth has " +
                   std::to_string(free) + " free particles (3 values each)");
        auto cache = std::make_unique<ImplicitEulerCache>();
        cache->dv.resize(Eigen::Index(r.count(unknowns, 8, "dv value")));
        for (Eigen::Index i = 0; i < cache->dv.size(); ++i) {
            cache->dv[i] = r.f64();
            requireNumber(r, cache->dv[i], -kMaxSpeed, kMaxSpeed, "implicit Euler's last dv");
        }
        s.implicit.cache = std::move(cache);
        // Fresh for this cloth (the step observes these two revisions from the cloth itself).
        s.implicit.stamp.valid = true;
        s.implicit.stamp.built.topology = c.topologyRevision;
        s.implicit.stamp.built.mass = c.massRevision;
    }
    if (version >= 4) { // torn pieces' sleep (piece_sleep.cpp): frames each particle has been still
        const uint64_t still = r.u64();
        if (still != 0 && still != c.particleCount())
            r.fail("still frames for " + std::to_string(still) + " particles; the cloth has " +
                   std::to_string(c.particleCount()));
        sleep.stillFrames.resize(r.count(still, 2, "still frame count"));
        for (uint16_t& f : sleep.stillFrames) f = r.u16();
    }
    sleep.ballSettings = w.settings; // as after a frame: the next one compares with these
    if (version >= 5) { // balls' sleep (ball_sleep.cpp)
        const uint64_t balls = r.u64();
        if (balls != w.balls.size())
            r.fail("sleep of " + std::to_string(balls) + " balls; the world has " + std::to_string(w.balls.size()));
        for (size_t i = 0; i < w.balls.size(); ++i) {
            Ball& b = w.balls[i];
            b.stillFrames = r.u16();
            const uint8_t asleep = r.u8();
            if (asleep > 1) r.fail("ball " + std::to_string(i) + ": asleep is " + std::to_string(asleep) + ", not 0 or 1");
            if (asleep && b.v != Vec3::Zero())
                r.fail("ball " + std::to_string(i) + " is asleep with a velocity (a sleeping ball has none)");
            b.asleep = asleep == 1;
        }
    }
    r.endSection();
}

// The magic line and the version.
uint32_t readHeader(ByteReader& r, std::string_view bytes) {
    const size_t have = std::min(bytes.size(), kMagic.size());
    if (bytes.substr(0, have) != kMagic.substr(0, have))
        r.fail("not a clothtear world file (it does not start with '" + shownInMessage(kMagic) + "')");
    if (have < kMagic.size()) r.failAt(have, "the file ends inside the first line (truncated)");
    r.bytes(kMagic.size());
    if (r.left() < 4) r.failAt(kMagic.size(), "the file ends before the version number (truncated)");
    const uint32_t version = r.u32();
    const std::string reads = "versions " + std::to_string(kOldestWorldFileVersion) + " to " + std::to_string(kWorldFileVersion);
    if (version > kWorldFileVersion)
        r.fail("version " + std::to_string(version) + ": written by a newer clothtear; this one reads " + reads);
    if (version < kOldestWorldFileVersion)
        r.fail("unknown version " + std::to_string(version) + " (this clothtear reads " + reads + ")");
    return version;
}

World readWorld(ByteReader& r, std::string_view bytes) {
    const uint32_t version = readHeader(r, bytes);
    World w;
    r.beginSection(kSecSettings);
    readSettings(r, w.settings);
    r.endSection();
    r.beginSection(kSecMesh);
    w.restMesh = readMesh(r);
    w.restFrame = knifeFrame(w.restMesh.positions); // as World::rebuild sets it: the frame of cut strokes
    r.endSection();
    readCloth(r, w.cloth, version);
    // The inverse masses follow from flags, density and area shares; refreshInvMass also gives the
    // cloth a mass revision of its own.
    for (Index p = 0; p < w.cloth.particleCount(); ++p) w.cloth.refreshInvMass(p);
    if (w.cloth.particleCount() == 0) w.cloth.massRevision = nextUniqueRevision();
    readBodies(r, w);
    readWorldScalars(r, w);
    readStepState(r, w, w.stepState(), version);
    if (r.offset() != bytes.size())
        r.failAt(r.offset(), std::to_string(bytes.size() - r.offset()) + " bytes after the last section");
    return w;
}

} // namespace

Result<World> parseWorld(std::string_view bytes, const std::string& source) {
    if (bytes.empty()) return Result<World>::failure(source + ": empty file, not a clothtear world file");
    Result<World> result;
    try {
        ByteReader r(bytes);
        result.value = readWorld(r, bytes);
    } catch (const FormatError& e) {
        return Result<World>::failure(source + ": byte " + std::to_string(e.offset) + " (" + e.section + "): " + e.what);
    } catch (const std::bad_alloc&) {
        return Result<World>::failure(source + ": out of memory while reading");
    }
    // Every topology invariant, as after each tear: a file whose cloth breaks one is refused. With
    // as many entries in the particles' lists as triangle corners, validateCloth's two checks (each
    // corner lists its triangle, each listed triangle has the particle as a corner) leave no repeats.
    const Cloth& c = result.value.cloth;
    size_t listed = 0;
    for (const std::vector<Index>& tris : c.particleTris) listed += tris.size();
    std::string err = listed == 3 * c.triangles.size() ? validateCloth(c)
                                                      : "the particles list " + std::to_string(listed) + " triangle corners, the " +
                                                            std::to_string(c.triangles.size()) + " triangles have " +
                                                            std::to_string(3 * c.triangles.size());
    if (!err.empty()) return Result<World>::failure(source + ": the cloth fails validation: " + err);
    return result;
}

Result<World> loadWorld(const std::string& path) {
    std::string bytes;
    try {
        const FileLimits limits{kMaxWorldFileBytes, "a world file",
                                "a world file has at most " + std::to_string(kMaxWorldFileBytes >> 20) + " MiB"};
        if (std::string err = readWholeFile(path, bytes, limits); !err.empty()) return Result<World>::failure(err);
    } catch (const std::bad_alloc&) {
        return Result<World>::failure(path + ": out of memory while reading");
    }
    return parseWorld(bytes, path);
}

} // namespace clothtear
