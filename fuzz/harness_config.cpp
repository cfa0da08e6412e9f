// --config harness: accepted files name a known scene (or none) and only assignments that apply.
#include "harness.h"

#include "clothtear/config_file.h"
#include "clothtear/params.h"
#include "clothtear/scenes.h"

namespace clothtear::fuzz {

std::string fuzzConfig(std::string_view bytes) {
    const std::string source = "fuzz.cfg";
    const Result<ConfigFile> r = parseConfig(bytes, source);
    if (!r.ok())
        return checkMessage(r.error, source);
    const ConfigFile& c = r.value;
    // Scene names are those parseSceneName reads: a setup, obj:PATH or SETUP:obj:PATH.
    if (!c.scene.empty() && !parseSceneName(c.scene).ok())
        return "accepted unknown scene '" + c.scene + "'";
    Settings s;
    for (const std::string& a : c.assignments)
        if (std::string err = applyAssignment(s, a); !err.empty())
            return "accepted '" + a + "' that --set refuses: " + err;
    return {};
}

} // namespace clothtear::fuzz
