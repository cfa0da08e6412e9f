// OBJ importer harness: bytes -> parseObj -> buildCloth -> validateCloth, then a few forced tears and
// one simulated frame on small meshes, each checked.
#include "harness.h"

#include "clothtear/mesh.h"
#include "clothtear/random.h"
#include "clothtear/tear.h"
#include "clothtear/world.h"

namespace clothtear::fuzz {
namespace {

// Tears and a frame of simulation on meshes up to this size: enough to reach every tear mode on the
// shapes the importer lets through, small enough to keep thousands of inputs per second.
constexpr size_t kMaxSimulatedTriangles = 64;
constexpr int kTears = 6;

uint64_t seedOf(std::string_view bytes) {
    uint64_t h = 0xcbf29ce484222325ull;
    for (unsigned char c : bytes)
        h = (h ^ c) * 0x100000001b3ull;
    return h;
}

} // namespace

std::string fuzzObj(std::string_view bytes) {
    const std::string source = "fuzz.obj";
    const Result<MeshData> loaded = parseObj(bytes, source);
    if (!loaded.ok())
        return checkMessage(loaded.error, source);
    const MeshData& mesh = loaded.value;
    if (std::string err = checkMesh(mesh, source); !err.empty())
        return "accepted a mesh checkMesh refuses: " + err;
    Result<Cloth> built = buildCloth(mesh, 0.2f);
    if (!built.ok())
        return checkMessage(built.error, "mesh: "); // non-manifold edges
    Cloth& cloth = built.value;
    const double area = cloth.totalRestArea(), uvArea = cloth.totalUvArea();
    if (std::string err = validateCloth(cloth, area, uvArea); !err.empty())
        return "built an invalid cloth: " + err;
    if (cloth.triangles.size() > kMaxSimulatedTriangles)
        return {};

    Rng rng(seedOf(bytes));
    TearSettings settings;
    TearLog log;
    const TearContext ctx{settings, 0.0, &log};
    for (int i = 0; i < kTears; ++i) {
        forceTear(cloth, rng.below(uint32_t(cloth.springs.size())), ctx);
        if (std::string err = validateCloth(cloth, area, uvArea); !err.empty())
            return "after forced tear " + std::to_string(i + 1) + ": " + err;
    }
    World world;
    world.settings.check.finite = true;
    if (std::string err = world.rebuild(mesh); !err.empty())
        return "World::rebuild refused what buildCloth took: " + err;
    world.step();
    if (!world.finite)
        return "one frame went non-finite: " + world.nonFiniteWhere;
    return {};
}

} // namespace clothtear::fuzz
