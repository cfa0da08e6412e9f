// Seeded random meshes and tear sequences for topology fuzzing (test_topology_fuzz.cpp): the same
// seed gives the same mesh and the same tears on every platform (Rng, random.h).
#pragma once
#include "clothtear/mesh.h"
#include "clothtear/random.h"
#include "clothtear/tear.h"

#include <array>
#include <cstdint>
#include <string>

namespace topofuzz {

enum class MeshKind { Grid, Irregular, ObjLike, Count };
const char* meshKindName(MeshKind k);

// A random mesh of kind `k`:
//   Grid       makeGridMesh, 2..14 particles a side, random size
//   Irregular  makeIrregularMesh, random jitter and seed
//   ObjLike    OBJ text read by parseObj: a jittered grid of quads and triangles with holes (so
//              pieces and one-point connections), slivers, shuffled vertex and face order, negative
//              indices, faces with and without vt
// Returns the mesh; `objText` (when not null) gets the OBJ text of an ObjLike mesh.
clothtear::MeshData randomMesh(MeshKind k, clothtear::Rng& rng, std::string* objText = nullptr);

// Counts of a tear sequence.
struct TearStats {
    uint64_t tried = 0, torn = 0;
    uint64_t repeated = 0;           // tears of the spring just torn, or at the particle it touched
    uint64_t cutLines = 0;           // lines cut across the cloth
    uint64_t piecesCut = 0;          // pieces added by those cuts (connected components)
    std::array<uint64_t, 3> modes{}; // basic, weak point, one point
};

// Tears `count` springs of `cloth` by forceTear: random springs in random order, repeated tears at
// the same place, and lines cut right across the cloth. After every tear `check(tearNumber)` runs
// (the caller validates); it returns false to stop.
template <class Check>
TearStats randomTears(clothtear::Cloth& cloth, clothtear::Rng& rng, int count, Check&& check);

// Connected pieces of the cloth (triangles joined through shared particles).
size_t pieceCount(const clothtear::Cloth& cloth);

} // namespace topofuzz

#include "topology_gen_tears.h"
