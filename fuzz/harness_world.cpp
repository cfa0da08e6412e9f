// World file harness: bytes -> parseWorld. Accepted: the cloth passes validateCloth, the world saves
// and loads back to the same stateHash, and on small cloths one frame stays finite (when every
// parameter is within its safe range: outside it, blowing up is what the user asked for; see
// docs/bad-input.md) and the reloaded copy steps to the same hash. Refused: one line naming the file.
#include "harness.h"

#include "clothtear/params.h"
#include "clothtear/state_hash.h"
#include "clothtear/tear.h"
#include "clothtear/world_file.h"

namespace clothtear::fuzz {
namespace {

// A frame on cloths up to this size: thousands of inputs per second still.
constexpr size_t kMaxSimulatedTriangles = 64;

bool safeSettings(const Settings& s) {
    for (const ParamInfo& p : allParams()) {
        if (p.type != ParamType::Float && p.type != ParamType::Int) continue;
        const double v = getParam(s, p);
        if (v < p.safeMin || v > p.safeMax) return false;
    }
    return true;
}

} // namespace

std::string fuzzWorld(std::string_view bytes) {
    const std::string source = "fuzz.ctw";
    Result<World> loaded = parseWorld(bytes, source);
    if (!loaded.ok())
        return checkMessage(loaded.error, source);
    World& world = loaded.value;
    if (std::string err = validateCloth(world.cloth); !err.empty())
        return "accepted a cloth validateCloth refuses: " + err;
    std::string again;
    if (std::string err = serializeWorld(world, again); !err.empty())
        return "accepted a world it cannot save: " + err;
    Result<World> back = parseWorld(again, source);
    if (!back.ok())
        return "its own save does not load: " + back.error;
    if (stateHash(back.value) != stateHash(world))
        return "save then load changed the state hash";
    if (world.cloth.triangles.size() > kMaxSimulatedTriangles)
        return {};
    const bool mustStayFinite = safeSettings(world.settings);
    world.settings.check.finite = back.value.settings.check.finite = true;
    world.step();
    back.value.step();
    // A loaded state may be violent whatever the parameters (particles far apart, fast): a frame
    // that goes non-finite is allowed, as for any run, but never silently (it must say where).
    if (mustStayFinite && !world.finite && world.nonFiniteWhere.empty())
        return "one frame went non-finite without saying where";
    if (world.finite && stateHash(back.value) != stateHash(world))
        return "the reloaded world stepped to another state";
    return {};
}

} // namespace clothtear::fuzz
