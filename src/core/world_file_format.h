// The layout of a world file (docs/world-file.md), shared by the writer (world_file_write.cpp) and
// the reader (world_file_read.cpp): the magic line, the sections in their order, and the size of each
// fixed record, which the reader checks a count against before it allocates anything.
//
//   "clothtear world\n"  u32 version
//   section*: 4-byte tag, u64 length of the body, body
//
// Every number is little-endian; floats are IEEE 754 bit patterns (float32 for the live state as
// the World keeps it, float64 for rest data), so a loaded value is the saved value, bit for bit.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace clothtear::worldfile {

inline constexpr std::string_view kMagic = "clothtear world\n";

struct Section {
    char tag[5];      // four characters in the file
    const char* name; // in messages
};

// In file order; each appears exactly once.
enum SectionId : int {
    kSecSettings,
    kSecMesh,
    kSecCloth,
    kSecParticles,
    kSecSprings,
    kSecBends,
    kSecTriangles,
    kSecBalls,
    kSecDrivers,
    kSecWorld,
    kSecStep,
    kSectionCount
};
inline constexpr Section kSections[kSectionCount] = {
    {"SETS", "settings"}, {"MESH", "rest mesh"},    {"CLTH", "cloth"},     {"PART", "particles"},
    {"SPRG", "springs"},  {"BEND", "bend springs"}, {"TRIS", "triangles"}, {"BALL", "balls"},
    {"DRVR", "drivers"},  {"WRLD", "world"},        {"STEP", "step state"},
};

// Bytes of one record, as the count check before each array uses them.
inline constexpr size_t kSectionHeaderBytes = 4 + 8;
inline constexpr size_t kMeshVertexBytes = 3 * 8;                    // position
inline constexpr size_t kMeshTriangleBytes = 3 * 4 + 6 * 8;          // corners, corner UVs
inline constexpr size_t kParticleBytes = 3 * 4 + 3 * 4 + 8 + 3 * 8 + 1 + 4; // x, v, area share, rest, flags, triangle count
inline constexpr size_t kSpringBytes = 2 * 4 + 2 * 4 + 3 * 4;       // a, b, rest, weight, tri[2], bend
inline constexpr size_t kBendBytes = 2 * 4 + 2 * 4 + 4;             // a, b, rest, weight, edge
inline constexpr size_t kBendMemoryBytes = 3 * 4 + 4;                // curvature, reversal K, M, direction
inline constexpr size_t kTriangleBytes = 3 * 4 + 3 * 4 + 6 * 8 + 8;  // p, s, uv, rest area
inline constexpr size_t kBallBytes = 3 * 4 + 3 * 4 + 4 + 4;          // x, v, radius, mass
inline constexpr size_t kDriverBytes = 3 * 4 + 8;                    // velocity, particle count
inline constexpr size_t kWorldScalarBytes = 8 + 8 + 8 + 1 + 4 * 8 + 8 + 4 + 4 + 4 + 8 + 4 + 4; // 4 tear counts, knife strokes
inline constexpr size_t kMaxSettingBytes = 4096; // one "name=value" line of the settings

} // namespace clothtear::worldfile
