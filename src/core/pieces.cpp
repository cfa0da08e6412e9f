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

} // namespace

std::vector<Piece> findPieces(const Cloth& cloth) {
    const size_t n = cloth.particleCount();
    std::vector<Index> parent(n);
    std::iota(parent.begin(), parent.end(), Index(0));
    for (const Triangle& t : cloth.triangles)
        for (int k = 1; k < 3; ++k) {
            const Index a = findRoot(parent, t.p[0]), b = findRoot(parent, t.p[k]);
            if (a != b) parent[std::max(a, b)] = std::min(a, b);
        }
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
    for (size_t p = 0; p < n; ++p) {
        const int64_t k = pieceOf[findRoot(parent, Index(p))];
        if (k >= 0) pieces[size_t(k)].particles++;
    }
    for (Piece& piece : pieces) piece.mass = double(cloth.density) * piece.restArea;
    std::stable_sort(pieces.begin(), pieces.end(), [](const Piece& a, const Piece& b) {
        if (a.restArea != b.restArea) return a.restArea > b.restArea;
        return a.triangles < b.triangles;
    });
    return pieces;
}

} // namespace clothtear
