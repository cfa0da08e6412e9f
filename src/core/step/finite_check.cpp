// findNonFinite: one pass over the state, lowest index first, so the report is the same on every run.
#include "finite_check.h"

#include <sstream>

namespace clothtear {
namespace {

template <class V> std::string describe(const char* what, size_t index, const char* field, const V& value) {
    std::ostringstream o;
    o << what << " " << index << ": " << field << " (" << value[0] << ", " << value[1] << ", " << value[2]
      << ")";
    return o.str();
}

} // namespace

std::string findNonFinite(const Cloth& c, const std::vector<Ball>& balls, const ThreadBuffers* forces) {
    for (size_t p = 0; p < c.x.size(); ++p) {
        if (!c.x[p].allFinite())
            return describe("particle", p, "position", c.x[p]);
        if (!c.v[p].allFinite())
            return describe("particle", p, "velocity", c.v[p]);
    }
    for (size_t b = 0; b < balls.size(); ++b) {
        if (!balls[b].x.allFinite())
            return describe("ball", b, "position", balls[b].x);
        if (!balls[b].v.allFinite())
            return describe("ball", b, "velocity", balls[b].v);
    }
    if (forces) {
        // The lowest particle over all buffers: a particle's force is the sum of its buffers.
        size_t first = c.x.size();
        Eigen::Vector4f value = Eigen::Vector4f::Zero();
        for (const auto& buffer : forces->acc)
            for (size_t p = 0; p < std::min(first, buffer.size()); ++p)
                if (!buffer[p].head<3>().allFinite()) {
                    first = p;
                    value = buffer[p];
                    break;
                }
        // The spring groups' sums (spring_groups.h), x, y, z.
        if (forces->groupForcesSet)
            for (const ComponentArrays& g : forces->groupForces)
                for (size_t p = 0; p < std::min(first, c.x.size()); ++p) {
                    const Eigen::Vector4f f(g.component(0)[p], g.component(1)[p], g.component(2)[p], 0.f);
                    if (!f.allFinite()) {
                        first = p;
                        value = f;
                        break;
                    }
                }
        if (first < c.x.size())
            return describe("particle", first, "force", value);
    }
    return {};
}

} // namespace clothtear
