// Springs in groups of eight with evenly spaced ends: a grid's rows of horizontal, vertical,
// diagonal and bend-shear springs. kernels.h's loop gathers both ends of every spring from the packed
// copy and transposes them, which is most of its instructions; a group's ends are eight consecutive
// (or every other) particles, so its kernel reads them with plain vector loads from a copy of the
// particles with one array per component. On the 2 m curtain at 128 x 128 about 62 % of the springs
// fall in groups; an irregular mesh has almost none and runs kernels.h's loop as before.
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

// Six float arrays over the particles, `stride` floats apart, each with room for a vector load or
// store past its last particle (a group of stride 2 spans 16 floats): the particles' positions and
// velocities (x, y, z, vx, vy, vz) for the groups' kernel, and its forces (a thread's sums on the
// groups' first ends x, y, z, then on their second ends). A group adds into eight consecutive first
// ends and eight consecutive second ends; with one array for both, a horizontal spring's group
// would load the eight floats it had just stored shifted by one, which the CPU cannot forward from
// the store (3 x slower in a test loop than separate arrays).
struct ComponentArrays {
    std::vector<float> data;
    size_t stride = 0;
    void resize(size_t particles); // zeroes everything when the size changes
    float* component(int c) { return data.data() + size_t(c) * stride; }
    const float* component(int c) const { return data.data() + size_t(c) * stride; }
};

// Which kernel the groups run: the widest the CPU has (AVX2, else SSE2), or none (every spring
// through kernels.h's loop). CLOTHTEAR_SPRING_KERNEL=generic|sse2|avx2 picks one (tests compare
// them; a kernel the CPU lacks falls back to the next narrower one).
enum class GroupKernel : uint8_t { None, Sse2, Avx2 };
GroupKernel groupKernelInUse();

// The order of one kind of spring in the cache. Springs [0, count) of `springs` are sorted by the
// distance of their ends' indices; runs of eight with ends a + s j, b + s j (s = 1 or 2, the smaller
// index as a) become groups, ordered by their first particle so that a thread's chunk of them
// touches a band of the cloth. order[e] is the spring at entry e (groups first, 8 entries each,
// then the rest in mesh order); swapped[e] says the entry's ends are (b, a); groups[g].entry is
// relative to the kind's first entry.
struct SpringOrder {
    std::vector<Index> order;
    std::vector<uint8_t> swapped;
    std::vector<SpringGroup> groups;
};
SpringOrder groupSprings(const std::vector<Spring>& springs, size_t count, size_t particles, bool makeGroups);

// Forces of groups [g0, g1) (Hooke + damping, the formula of springForceScalar) added into
// `forces`. rest, k and kd are the cache's arrays, indexed by entry. The SSE2 and AVX2 kernels give
// the same bits: the same operations lane by lane, no fused multiply-add, and one addition per
// group into each float it touches, in group order.
void springForcesGrouped(GroupKernel kernel, const SpringGroup* groups, size_t g0, size_t g1, const float* rest,
                         const float* k, const float* kd, const ComponentArrays& particles, ComponentArrays& forces);

} // namespace clothtear
