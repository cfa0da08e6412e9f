// Random meshes for topology fuzzing (topology_gen.h).
#include "topology_gen.h"

#include "clothtear/cloth.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace topofuzz {
using namespace clothtear;

const char* meshKindName(MeshKind k) {
    static const char* names[] = {"grid", "irregular", "obj-like"};
    return names[int(k)];
}

namespace {

// An OBJ file as a modeller might write it (see randomMesh), read back through the importer.
MeshData objLikeMesh(Rng& rng, std::string* objText) {
    const int nx = 3 + int(rng.below(10)), ny = 3 + int(rng.below(10));
    const double spacing = rng.uniform(0.05, 0.5);
    std::vector<Vec3d> v;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const double jx = (i > 0 && i < nx - 1) ? rng.uniform(-0.3, 0.3) : 0.0;
            const double jy = (j > 0 && j < ny - 1) ? rng.uniform(-0.3, 0.3) : 0.0;
            v.emplace_back((i + jx) * spacing, -(j + jy) * spacing,
                           0.05 * spacing * std::sin(1.7 * i + 0.9 * j));
        }
    auto at = [&](int i, int j) { return j * nx + i; };
    std::vector<std::vector<int>> faces; // 0-based corners
    for (int j = 0; j + 1 < ny; ++j)
        for (int i = 0; i + 1 < nx; ++i) {
            const int a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
            const double pick = rng.uniform();
            if (pick < 0.15)
                continue; // a hole
            if (pick < 0.45) {
                faces.push_back({a, b, c, d}); // a quad, fan-triangulated by the importer
            } else if (pick < 0.55) {
                // A sliver: an extra vertex just inside edge a-b, a fan of four around it.
                const double height = spacing * std::pow(10.0, rng.uniform(-5.0, -2.0));
                const Vec3d mid = 0.5 * (v[a] + v[b]);
                const Vec3d inward = (0.5 * (v[c] + v[d]) - mid).normalized();
                v.push_back(mid + height * inward);
                const int e = int(v.size()) - 1;
                faces.push_back({a, b, e});
                faces.push_back({b, c, e});
                faces.push_back({c, d, e});
                faces.push_back({d, a, e});
            } else if (rng.uniform() < 0.5) {
                faces.push_back({a, b, c});
                faces.push_back({a, c, d});
            } else {
                faces.push_back({a, b, d});
                faces.push_back({b, c, d});
            }
        }
    if (faces.empty())
        faces.push_back({at(0, 0), at(1, 0), at(1, 1)});
    if (rng.uniform() < 0.4) {
        // An island: a separate patch beside the grid (OBJ files often hold several pieces).
        const int base = int(v.size());
        const double x0 = (nx + 0.5) * spacing;
        for (int k = 0; k < 4; ++k)
            v.emplace_back(x0 + (k % 3 ? spacing : 0.0), -(k / 2) * spacing, 0.0);
        faces.push_back({base, base + 1, base + 2});
        faces.push_back({base, base + 2, base + 3});
    }
    // Shuffled vertex order (file index of each vertex), face order, first corner and winding.
    std::vector<int> fileIndex(v.size());
    std::iota(fileIndex.begin(), fileIndex.end(), 0);
    for (size_t i = fileIndex.size(); i > 1; --i)
        std::swap(fileIndex[i - 1], fileIndex[rng.below(uint32_t(i))]);
    std::vector<int> vertexAt(v.size());
    for (size_t k = 0; k < v.size(); ++k)
        vertexAt[fileIndex[k]] = int(k);
    for (size_t i = faces.size(); i > 1; --i)
        std::swap(faces[i - 1], faces[rng.below(uint32_t(i))]);
    Vec3d lo = v[0], hi = v[0];
    for (const Vec3d& p : v)
        lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    std::string text = "# clothtear topology fuzz mesh\no cloth\n";
    char line[160];
    for (size_t k = 0; k < v.size(); ++k) {
        const Vec3d& p = v[vertexAt[k]];
        std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", p.x(), p.y(), p.z());
        text += line;
    }
    int vtCount = 0;
    for (auto& f : faces) {
        std::rotate(f.begin(), f.begin() + rng.below(uint32_t(f.size())), f.end());
        if (rng.uniform() < 0.3)
            std::reverse(f.begin(), f.end());
        const bool uv = rng.uniform() < 0.6, relative = rng.uniform() < 0.2;
        std::string face = "f";
        for (int corner : f) {
            if (uv) {
                const Vec3d& p = v[corner];
                std::snprintf(line, sizeof line, "vt %.17g %.17g\n", (p.x() - lo.x()) / (hi.x() - lo.x()),
                              (p.y() - lo.y()) / (hi.y() - lo.y()));
                text += line;
                ++vtCount;
            }
            const long vi = relative ? long(fileIndex[corner]) - long(v.size()) : long(fileIndex[corner]) + 1;
            face += ' ';
            face += std::to_string(vi);
            if (uv) {
                face += '/';
                face += std::to_string(vtCount);
            }
        }
        text += face + "\n";
    }
    if (objText)
        *objText = text;
    return parseObj(text, "topofuzz.obj").value; // the caller checks it built (a generator bug otherwise)
}

} // namespace

MeshData randomMesh(MeshKind k, Rng& rng, std::string* objText) {
    const int nx = 2 + int(rng.below(13)), ny = 2 + int(rng.below(13));
    const double w = rng.uniform(0.2, 4.0), h = rng.uniform(0.2, 4.0);
    switch (k) {
    case MeshKind::Grid:
        return makeGridMesh(nx, ny, w, h);
    case MeshKind::Irregular:
        return makeIrregularMesh(std::max(nx, 3), std::max(ny, 3), w, h, rng.uniform(0.0, 0.45),
                                 uint32_t(rng.next()));
    default:
        return objLikeMesh(rng, objText);
    }
}

size_t pieceCount(const Cloth& c) {
    std::vector<Index> parent(c.particleCount());
    std::iota(parent.begin(), parent.end(), Index(0));
    auto find = [&](Index p) {
        while (parent[p] != p)
            p = parent[p] = parent[parent[p]];
        return p;
    };
    for (const Triangle& t : c.triangles)
        for (int i = 1; i < 3; ++i)
            parent[find(t.p[i])] = find(t.p[0]);
    size_t pieces = 0;
    for (Index p = 0; p < c.particleCount(); ++p)
        pieces += !c.particleTris[p].empty() && find(p) == p;
    return pieces;
}

} // namespace topofuzz
