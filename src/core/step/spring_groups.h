// Springs in groups of eight with evenly spaced ends: a grid's rows of horizontal, vertical,
// diagonal and bend-shear springs. kernels.h's loop gathers both ends of every spring from the packed
// copy and transposes them, which is most of its instructions; a group's ends are eight consecutive
// (or every other) particles, so its kernel reads them with plain vector loads from a copy of the
// particles with one array per component. In groups: 93 % of the springs of the 128 x 128 curtain,
// 81 % at 40 x 40, a third of the irregular mesh (a jittered grid); an OBJ mesh in its own order
// has few, and the rest runs kernels.h's loop as before (bench/README.md, "The spring groups").
#pragma once
#include "clothtear/cloth.h"

#include <cstdint>
#include <vector>

namespace clothtear {

inline constexpr size_t kGroupSize = 8;

// Cache entries [entry, entry + 8) join particles a + stride j and b + stride j (j = 0..7).
struct SpringGroup {
    uint32_t entry, a, b, stride;
};

// Float arrays over the particles, one per component, `stride` floats apart, each with room for a
// vector load or store past its last particle (a group of stride 2 spans 16 floats): the
// particles' positions and velocities (x, y, z, vx, vy, vz) for the groups' kernel, and a thread's
// sums of its groups' forces (x, y, z), which the integrator adds to the other forces.
struct ComponentArrays {
    std::vector<float> data;
    size_t stride = 0;
    int components = 0;
    void resize(size_t particles, int count); // zeroes everything when the size changes
    float* component(int c) { return data.data() + size_t(c) * stride; }
    const float* component(int c) const { return data.data() + size_t(c) * stride; }
};

// Which kernel the groups run: the widest the CPU has (AVX2, else SSE2), or none (every spring
// through kernels.h's loop). CLOTHTEAR_SPRING_KERNEL=generic|sse2|avx2 picks one (tests compare
// them; a kernel the CPU lacks falls back to the next narrower one).
enum class GroupKernel : uint8_t { None, Sse2, Avx2 };
GroupKernel groupKernelInUse();

// Springs are ordered by bands of 2^kBandShift first particles (their smaller end's index).
inline constexpr unsigned kBandShift = 10;

// One band of one kind of spring: groups [groupsBegin, groupsEnd), whose entries come first, then
// the other springs at entries [restBegin, restEnd).
struct SpringBand {
    uint32_t groupsBegin = 0, groupsEnd = 0, restBegin = 0, restEnd = 0;
};

// The order of one kind of spring in the cache. Springs [0, count) of `springs` are sorted by the
// distance of their ends' indices; runs of eight with ends a + s j, b + s j (s = 1 or 2, the smaller
// index as a) become groups. Then band by band (groupSprings says why): the band's groups, 8
// entries each, then its other springs in mesh order. order[e] is the spring at entry e (its ends
// as the spring has them; a group's kernel reads its own a and b); entries and group indices are
// relative to the kind's first entry and first group. Without makeGroups: one band, every spring in
// mesh order.
struct SpringOrder {
    std::vector<Index> order;
    std::vector<SpringGroup> groups;
    std::vector<SpringBand> bands;
};
SpringOrder groupSprings(const std::vector<Spring>& springs, size_t count, size_t particles, bool makeGroups);

// Forces of groups [g0, g1) (Hooke + damping, the formula of springForceScalar) added into
// `forces`. rest, k and kd are the cache's arrays, indexed by entry. The SSE2 and AVX2 kernels give
// the same bits: the same operations lane by lane, no fused multiply-add, and one addition per
// group into each float it touches, in group order.
// Which terms of the spring force f = (k (L - L0) + kd (v_b - v_a).n) n a pass computes. With the
// damping taken implicitly (time.damping, integrate.cpp) a sub-step runs two passes, the elastic
// one on the positions and the damping one on the velocities the other forces gave; each leaves
// out the other's loads and arithmetic (the velocities, or the rest lengths and stiffnesses). A
// term left out adds exactly what a zero k or kd would have added (a signed zero).
enum class SpringTerms : uint8_t { Both, Elastic, Damping };

void springForcesGrouped(GroupKernel kernel, SpringTerms terms, const SpringGroup* groups, size_t g0, size_t g1,
                         const float* rest, const float* k, const float* kd, const ComponentArrays& particles,
                         ComponentArrays& forces);

} // namespace clothtear
