// stateHash: FNV-1a (Fowler-Noll-Vo, 64-bit) over the world's state, one field at a time.
#include "clothtear/state_hash.h"

#include "step/step_state.h"

#include <cstdio>
#include <type_traits>
#include <vector>

namespace clothtear {
namespace {

class Fnv1a {
  public:
    uint64_t value = 0xcbf29ce484222325ull; // offset basis
    void bytes(const void* data, size_t size) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < size; ++i)
            value = (value ^ p[i]) * 0x100000001b3ull; // FNV prime
    }
    template <class T> void scalar(T v) {
        static_assert(std::is_arithmetic_v<T>);
        bytes(&v, sizeof v);
    }
    // Arrays of scalars or of Eigen fixed-size vectors (contiguous, no padding: Vector3f is 12 bytes).
    template <class T> void array(const std::vector<T>& v) {
        scalar(uint64_t(v.size()));
        if constexpr (std::is_arithmetic_v<T>)
            bytes(v.data(), v.size() * sizeof(T));
        else
            for (const T& e : v)
                bytes(e.data(), sizeof(typename T::Scalar) * size_t(e.size()));
    }
};

} // namespace

uint64_t stateHash(const World& w) {
    const Cloth& c = w.cloth;
    Fnv1a h;
    h.array(c.x);
    h.array(c.v);
    h.array(c.invMass);
    h.array(c.flags);
    h.array(c.rest);
    h.array(c.areaShare);
    for (const std::vector<Spring>* springs : {&c.springs, &c.bends}) {
        h.scalar(uint64_t(springs->size()));
        for (const Spring& s : *springs) {
            h.scalar(s.a);
            h.scalar(s.b);
            h.scalar(s.rest);
            h.scalar(s.weight);
        }
    }
    for (const SpringTopo& t : c.springTopo) {
        h.scalar(t.tri[0]);
        h.scalar(t.tri[1]);
        h.scalar(t.bend);
    }
    h.array(c.bendEdge);
    // kes hinges' memory: part of the state that decides the next step; empty (and not hashed, so
    // the golden hashes of the linear model stay) until a kes step.
    if (!c.bendMemory.empty()) {
        h.scalar(uint64_t(c.bendMemory.size()));
        for (const BendMemory& m : c.bendMemory)
            h.scalar(m.extremeK), h.scalar(m.reversalK), h.scalar(m.reversalM), h.scalar(m.direction);
    }
    h.scalar(uint64_t(c.triangles.size()));
    for (const Triangle& t : c.triangles) {
        for (int i = 0; i < 3; ++i) {
            h.scalar(t.p[i]);
            h.scalar(t.s[i]);
            h.bytes(t.uv[i].data(), 2 * sizeof(double));
        }
        h.scalar(t.restArea);
    }
    h.scalar(c.topologyRevision);
    h.scalar(uint64_t(w.balls.size()));
    for (const Ball& b : w.balls) {
        h.bytes(b.x.data(), 3 * sizeof(float));
        h.bytes(b.v.data(), 3 * sizeof(float));
        h.scalar(b.radius);
        h.scalar(b.mass);
    }
    h.scalar(uint64_t(w.drivers.size()));
    for (const Driver& d : w.drivers) {
        h.array(d.particles);
        h.bytes(d.velocity.data(), 3 * sizeof(float));
    }
    // Integrator state that outlives a step: Verlet's half kicks (its next step reads them).
    const StepState& state = w.stepState();
    h.scalar(uint8_t(state.verletRunning));
    h.array(state.verletKick);
    h.scalar(w.time);
    h.scalar(w.steps);
    return h.value;
}

std::string hashHex(uint64_t hash) {
    char buf[24];
    std::snprintf(buf, sizeof buf, "0x%016llx", static_cast<unsigned long long>(hash));
    return buf;
}

} // namespace clothtear
