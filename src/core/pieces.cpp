// Connected islands by union-find over particles: every triangle joins its three corners.
#include "clothtear/pieces.h"

#include <algorithm>
#include <numeric>

namespace clothtear {
namespace {

Index findRoot(std::vector<Index>& parent, Index p) {
    while (parent[p] != p) {
        parent[p] = parent[parent[p]]; // path halving
        p = parent[p];
    }
    return p;
}

// Union-find over particles, each triangle joining its corners; the roots are the lowest-numbered
// particle of each island.
std::vector<Index> unionOfTriangles(const Cloth& cloth) {
    std::vector<Index> parent(cloth.particleCount());
    std::iota(parent.begin(), parent.end(), Index(0));
    for (const Triangle& t : cloth.triangles)
        for (int k = 1; k < 3; ++k) {
            const Index a = findRoot(parent, t.p[0]), b = findRoot(parent, t.p[k]);
            if (a != b) parent[std::max(a, b)] = std::min(a, b);
        }
    return parent;
}

} // namespace

std::vector<Index> pieceLabels(const Cloth& cloth) {
    std::vector<Index> parent = unionOfTriangles(cloth);
    std::vector<Index> label(cloth.particleCount(), kNone);
    for (Index p = 0; p < label.size(); ++p)
        if (!cloth.particleTris[p].empty()) label[p] = findRoot(parent, p);
    return label;
}

std::vector<double> restAreaByLabel(const Cloth& cloth, const std::vector<Index>& label, double& total) {
    std::vector<double> area(cloth.particleCount(), 0.0);
    total = 0;
    for (const Triangle& t : cloth.triangles) {
        if (label[t.p[0]] != kNone) area[label[t.p[0]]] += t.restArea;
        total += t.restArea;
    }
    return area;
}

std::vector<Piece> findPieces(const Cloth& cloth) {
    const size_t n = cloth.particleCount();
    std::vector<Index> parent = unionOfTriangles(cloth);
    // One piece per root that owns a triangle, numbered in order of its first triangle (the sort
    // below is stable, so that order breaks ties).
    std::vector<int64_t> pieceOf(n, -1);
    std::vector<Piece> pieces;
    for (size_t i = 0; i < cloth.triangles.size(); ++i) {
        const Triangle& t = cloth.triangles[i];
        const Index r = findRoot(parent, t.p[0]);
        if (pieceOf[r] < 0) {
            pieceOf[r] = int64_t(pieces.size());
            pieces.emplace_back().firstTriangle = Index(i);
        }
        Piece& piece = pieces[size_t(pieceOf[r])];
        piece.triangles++;
        piece.restArea += t.restArea;
    }
    std::vector<size_t> asleep(pieces.size(), 0);
    for (size_t p = 0; p < n; ++p) {
        const int64_t k = pieceOf[findRoot(parent, Index(p))];
        if (k < 0) continue;
        pieces[size_t(k)].particles++;
        asleep[size_t(k)] += cloth.asleep(Index(p));
    }
    for (size_t k = 0; k < pieces.size(); ++k) {
        pieces[k].mass = double(cloth.density) * pieces[k].restArea;
        pieces[k].asleep = asleep[k] == pieces[k].particles;
    }
    std::stable_sort(pieces.begin(), pieces.end(), [](const Piece& a, const Piece& b) {
        if (a.restArea != b.restArea) return a.restArea > b.restArea;
        return a.triangles < b.triangles;
    });
    return pieces;
}

} // namespace clothtear
