// Coarse blocks of a grid cloth for drawing from far (render_lod.h).
#include "render_lod.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace clothtear::app {
namespace {

// The most frequent non-zero step along one UV axis over a sample of triangle edges (a grid's cell
// size; tears add half steps, far fewer). 0 when there is none.
double latticeStep(const Cloth& cloth, int axis) {
    const size_t n = cloth.triangles.size();
    const size_t stride = std::max<size_t>(1, n / 4096);
    std::vector<double> steps;
    for (size_t t = 0; t < n; t += stride)
        for (int c = 0; c < 3; ++c) {
            const double d = std::abs(cloth.triangles[t].uv[(c + 1) % 3][axis] - cloth.triangles[t].uv[c][axis]);
            if (d > 1e-12) steps.push_back(d);
        }
    if (steps.empty()) return 0;
    std::sort(steps.begin(), steps.end());
    double best = 0;
    size_t bestRun = 0;
    for (size_t i = 0; i < steps.size();) {
        size_t j = i;
        while (j < steps.size() && steps[j] - steps[i] <= 1e-4 * steps[i]) ++j;
        if (j - i > bestRun) bestRun = j - i, best = steps[i];
        i = j;
    }
    return best;
}

// Block states, and what an intact block knows: the render vertex at each of its 3 x 3 lattice points.
struct Block {
    std::array<uint32_t, 9> vertex;
    uint8_t triangles = 0;
    bool broken = false;  // a triangle off the lattice, too big, or a lattice point with two vertices
    bool emitted = false;
    Block() { vertex.fill(~0u); }
    bool intact() const {
        if (broken || triangles != 8) return false;
        for (uint32_t v : vertex)
            if (v == ~0u) return false;
        return true;
    }
};

} // namespace

std::vector<uint32_t> coarseGridIndices(const Cloth& cloth, const RenderMesh& mesh) {
    const size_t n = cloth.triangles.size();
    if (n == 0 || mesh.indices.size() != 3 * n) return {};
    const double du = latticeStep(cloth, 0), dv = latticeStep(cloth, 1);
    if (!(du > 0) || !(dv > 0)) return {};
    double u0 = 1e300, v0 = 1e300, u1 = -1e300, v1 = -1e300;
    for (const Triangle& t : cloth.triangles)
        for (const Vec2d& uv : t.uv) {
            u0 = std::min(u0, uv.x()), v0 = std::min(v0, uv.y());
            u1 = std::max(u1, uv.x()), v1 = std::max(v1, uv.y());
        }
    const long ni = std::lround((u1 - u0) / du) / 2 + 1, nj = std::lround((v1 - v0) / dv) / 2 + 1;
    if (ni <= 0 || nj <= 0 || double(ni) * double(nj) > 4.0 * double(n) + 16) return {}; // not a grid
    std::vector<Block> blocks(size_t(ni) * size_t(nj));
    // Each triangle: its lattice coordinates, its cell, its block.
    std::vector<int32_t> blockOf(n, -1);
    for (size_t t = 0; t < n; ++t) {
        const Triangle& tri = cloth.triangles[t];
        double fi[3], fj[3];
        long li[3], lj[3];
        bool onLattice = true;
        for (int c = 0; c < 3; ++c) {
            fi[c] = (tri.uv[c].x() - u0) / du, fj[c] = (tri.uv[c].y() - v0) / dv;
            li[c] = std::lround(fi[c]), lj[c] = std::lround(fj[c]);
            onLattice &= std::abs(fi[c] - double(li[c])) < 1e-3 && std::abs(fj[c] - double(lj[c])) < 1e-3;
        }
        const long ci = long(std::floor(std::min({fi[0], fi[1], fi[2]}) + 1e-3));
        const long cj = long(std::floor(std::min({fj[0], fj[1], fj[2]}) + 1e-3));
        const long bi = ci >> 1, bj = cj >> 1;
        if (bi < 0 || bj < 0 || bi >= ni || bj >= nj) continue; // outside: drawn as it is
        Block& b = blocks[size_t(bj) * size_t(ni) + size_t(bi)];
        blockOf[t] = int32_t(bj * ni + bi);
        ++b.triangles;
        if (!onLattice) {
            b.broken = true;
            continue;
        }
        for (int c = 0; c < 3; ++c) {
            const long i = li[c] - 2 * bi, j = lj[c] - 2 * bj;
            if (i < 0 || i > 2 || j < 0 || j > 2 || li[c] - ci > 1 || lj[c] - cj > 1) {
                b.broken = true;
                break;
            }
            uint32_t& slot = b.vertex[size_t(j * 3 + i)];
            const uint32_t v = mesh.indices[3 * t + size_t(c)];
            if (slot == ~0u) slot = v;
            else if (slot != v) b.broken = true; // two copies of one point: torn inside the block
        }
    }
    // Drawn fine (has triangles, not intact): its sides with an intact block keep their midpoints.
    auto fine = [&](long bi, long bj) {
        if (bi < 0 || bj < 0 || bi >= ni || bj >= nj) return false;
        const Block& b = blocks[size_t(bj) * size_t(ni) + size_t(bi)];
        return b.triangles > 0 && !b.intact();
    };
    std::vector<uint32_t> out;
    out.reserve(mesh.indices.size() / 3);
    bool anyCoarse = false;
    for (size_t t = 0; t < n; ++t) {
        Block* b = blockOf[t] >= 0 ? &blocks[size_t(blockOf[t])] : nullptr;
        if (!b || !b->intact()) {
            out.insert(out.end(), mesh.indices.begin() + long(3 * t), mesh.indices.begin() + long(3 * t + 3));
            continue;
        }
        if (b->emitted) continue;
        b->emitted = anyCoarse = true;
        const long bi = blockOf[t] % ni, bj = blockOf[t] / ni;
        const auto at = [&](int i, int j) { return b->vertex[size_t(j * 3 + i)]; };
        // The sides counter-clockwise in UV (the cloth's winding): corner, midpoint, next corner, and
        // the block across.
        const std::array<std::array<int, 6>, 4> sides{{{0, 0, 1, 0, 2, 0}, {2, 0, 2, 1, 2, 2}, {2, 2, 1, 2, 0, 2}, {0, 2, 0, 1, 0, 0}}};
        const std::array<std::array<long, 2>, 4> across{{{bi, bj - 1}, {bi + 1, bj}, {bi, bj + 1}, {bi - 1, bj}}};
        bool anyMid = false;
        std::array<bool, 4> mid{};
        for (int k = 0; k < 4; ++k) anyMid |= mid[size_t(k)] = fine(across[size_t(k)][0], across[size_t(k)][1]);
        if (!anyMid) {
            out.insert(out.end(), {at(0, 0), at(2, 0), at(2, 2), at(0, 0), at(2, 2), at(0, 2)});
            continue;
        }
        for (int k = 0; k < 4; ++k) {
            const auto& s = sides[size_t(k)];
            if (mid[size_t(k)])
                out.insert(out.end(), {at(1, 1), at(s[0], s[1]), at(s[2], s[3]), at(1, 1), at(s[2], s[3]), at(s[4], s[5])});
            else
                out.insert(out.end(), {at(1, 1), at(s[0], s[1]), at(s[4], s[5])});
        }
    }
    if (!anyCoarse) return {};
    return out;
}

float pixelsPerMetre(float distance, float fovY, float heightPixels) {
    return heightPixels / (2.f * std::tan(0.5f * fovY) * std::max(distance, 1e-6f));
}

} // namespace clothtear::app
