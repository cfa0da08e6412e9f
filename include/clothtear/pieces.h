// Torn pieces: the connected islands of a cloth. Two triangles belong to one piece when a chain of
// triangles sharing particles joins them (a one-point connection, Onal 3.2.3, still holds its two
// parts together). Computed on demand from the topology (the report, the stats pane, tests).
#pragma once
#include "clothtear/cloth.h"

#include <vector>

namespace clothtear {

struct Piece {
    size_t triangles = 0;
    size_t particles = 0;
    double restArea = 0; // m^2: the rest area of its triangles
    double mass = 0;     // kg: density x rest area
    Index firstTriangle = kNone; // its lowest-numbered triangle (World::deletePiece takes it)
    bool asleep = false;         // settled and not simulated (src/core/step/piece_sleep.cpp)
};

// Per particle, the piece it belongs to, named by the piece's lowest-numbered particle; kNone for a
// particle no triangle uses.
std::vector<Index> pieceLabels(const Cloth& cloth);

// The rest area of each piece (m^2), indexed by its label (pieceLabels: a particle index; 0 where no
// piece has that label), and the whole cloth's rest area in `total`.
std::vector<double> restAreaByLabel(const Cloth& cloth, const std::vector<Index>& label, double& total);

// The pieces of `cloth`, largest rest area first (ties: fewer triangles first, then the order in
// which their first triangles appear). An untorn cloth is one piece with its whole rest area.
std::vector<Piece> findPieces(const Cloth& cloth);

} // namespace clothtear
