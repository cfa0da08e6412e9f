// Rectangular cloth meshes: the regular grid and the irregular (jittered) triangulation.
#include "clothtear/cloth.h"
#include "clothtear/mesh.h"
#include "clothtear/random.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace clothtear {
namespace {

Index gridIndex(int i, int j, int nx) { return static_cast<Index>(j * nx + i); }

// Corner UVs from rest positions: u across the width, v up the height (v = 1 at the top edge).
Vec2d uvOf(const Vec3d& p, double width, double height) {
    return Vec2d((p.x() + 0.5 * width) / width, (p.y() + 0.5 * height) / height);
}

void addTriangle(MeshData& m, Index a, Index b, Index c, const std::vector<Vec2d>& uv) {
    m.triangles.push_back({a, b, c});
    m.cornerUVs.push_back({uv[a], uv[b], uv[c]});
}

// Quad corners: tl=(i,j) tr=(i+1,j) bl=(i,j+1) br=(i+1,j+1); j grows downwards, y grows upwards.
//   along bl-tr:  tl---tr      along tl-br:  tl---tr
//                 |   / |                    | \   |
//                 | /   |                    |   \ |
//                 bl---br                    bl---br
// Both triangles of each split are counter-clockwise in (x, y) and therefore in UV.
void splitQuad(MeshData& m, Index tl, Index tr, Index bl, Index br, bool alongBlTr, const std::vector<Vec2d>& uv) {
    if (alongBlTr) {
        addTriangle(m, bl, br, tr, uv);
        addTriangle(m, bl, tr, tl, uv);
    } else {
        addTriangle(m, tl, bl, br, uv);
        addTriangle(m, tl, br, tr, uv);
    }
}

MeshData makeRectangle(int nx, int ny, double width, double height, double jitter, uint32_t seed, bool irregular) {
    MeshData m;
    const double hx = width / (nx - 1), hy = height / (ny - 1);
    Rng rng(seed);
    m.positions.reserve(size_t(nx) * ny);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            double x = -0.5 * width + i * hx, y = 0.5 * height - j * hy;
            if (irregular) {
                // Border vertices slide only along their border so the outline stays a rectangle.
                if (i > 0 && i < nx - 1) x += rng.uniform(-jitter, jitter) * hx;
                if (j > 0 && j < ny - 1) y += rng.uniform(-jitter, jitter) * hy;
            }
            m.positions.emplace_back(x, y, 0.0);
        }
    std::vector<Vec2d> uv(m.positions.size());
    for (size_t k = 0; k < uv.size(); ++k) uv[k] = uvOf(m.positions[k], width, height);
    m.triangles.reserve(size_t(nx - 1) * (ny - 1) * 2);
    for (int j = 0; j + 1 < ny; ++j)
        for (int i = 0; i + 1 < nx; ++i) {
            const Index tl = gridIndex(i, j, nx), tr = gridIndex(i + 1, j, nx);
            const Index bl = gridIndex(i, j + 1, nx), br = gridIndex(i + 1, j + 1, nx);
            bool alongBlTr = ((i + j) % 2) == 0; // alternating diagonals
            if (irregular) {
                // Shorter diagonal, unless that would fold a triangle of a non-convex quad.
                alongBlTr = (m.positions[bl] - m.positions[tr]).squaredNorm() <
                            (m.positions[tl] - m.positions[br]).squaredNorm();
                auto ccw = [&](Index a, Index b, Index c) { return uvArea(uv[a], uv[b], uv[c]) > 0; };
                const bool okBlTr = ccw(bl, br, tr) && ccw(bl, tr, tl);
                const bool okTlBr = ccw(tl, bl, br) && ccw(tl, br, tr);
                if (alongBlTr && !okBlTr) alongBlTr = false;
                if (!alongBlTr && !okTlBr) alongBlTr = true;
            }
            splitQuad(m, tl, tr, bl, br, alongBlTr, uv);
        }
    return m;
}

} // namespace

MeshData makeGridMesh(int nx, int ny, double width, double height) {
    return makeRectangle(nx, ny, width, height, 0.0, 0, false);
}

MeshData makeIrregularMesh(int nx, int ny, double width, double height, double jitter, uint32_t seed) {
    return makeRectangle(nx, ny, width, height, jitter, seed, true);
}

std::string checkMesh(const MeshData& mesh, const std::string& source) {
    if (mesh.cornerUVs.size() != mesh.triangles.size()) return source + ": UV count does not match triangle count";
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        if (!mesh.positions[v].allFinite())
            return source + ": vertex " + std::to_string(v + 1) + " has a non-finite coordinate";
        if (mesh.positions[v].cwiseAbs().maxCoeff() > kMaxCoordinate)
            return source + ": vertex " + std::to_string(v + 1) + " lies beyond +-" + std::to_string(int(kMaxCoordinate)) +
                   " m of the origin";
    }
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        const std::string face = source + ": face " + std::to_string(t + 1);
        for (Index v : tri)
            if (v >= mesh.positions.size())
                return face + " refers to vertex " + std::to_string(v + 1) + " but there are only " +
                       std::to_string(mesh.positions.size());
        const auto& uv = mesh.cornerUVs[t];
        for (const Vec2d& c : uv) {
            if (!c.allFinite()) return face + " has a non-finite UV";
            if (c.cwiseAbs().maxCoeff() > kMaxUv) return face + " has a texture coordinate beyond +-1e6";
        }
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) return face + " repeats a vertex";
        const Vec3d& a = mesh.positions[tri[0]];
        const Vec3d& b = mesh.positions[tri[1]];
        const Vec3d& c = mesh.positions[tri[2]];
        const double scale = std::max({(b - a).squaredNorm(), (c - a).squaredNorm(), (c - b).squaredNorm()});
        if (!(triangleArea(a, b, c) > 1e-12 * scale) || scale == 0.0) return face + " is degenerate (zero area)";
        const double shortest = std::sqrt(std::min({(b - a).squaredNorm(), (c - a).squaredNorm(), (c - b).squaredNorm()}));
        if (shortest < kMinEdge) {
            char len[32];
            std::snprintf(len, sizeof len, "%.3g", shortest);
            return face + " has an edge of " + len + " m; edges under 1e-7 m are refused";
        }
        const double uvScale = std::max({(uv[1] - uv[0]).squaredNorm(), (uv[2] - uv[0]).squaredNorm(),
                                         (uv[2] - uv[1]).squaredNorm()});
        if (!(std::abs(uvArea(uv[0], uv[1], uv[2])) > 1e-12 * uvScale))
            return face + " has texture coordinates with zero area (the texture cannot follow it when it tears)";
    }
    return {};
}

} // namespace clothtear
