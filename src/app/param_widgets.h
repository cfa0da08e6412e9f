// Generic ImGui widgets for the parameter table (params.h): one slider, checkbox or combo per row, with
// unit, range and help taken from the table, so adding a parameter to the core adds it to the panel.
#pragma once
#include "clothtear/params.h"

#include <string_view>

namespace clothtear::app {

enum class ParamEdit {
    None,
    Changed,   // the value changed (a slider being dragged)
    Committed, // the edit is finished (slider released, checkbox/combo picked)
};

// `allowUnsafe` spans the hard range instead of the safe one (Keserica 6.2: people may push the
// simulation past its stable range on purpose).
ParamEdit paramWidget(Settings& settings, const ParamInfo& param, bool allowUnsafe);

// Every parameter whose name starts with `prefix` (e.g. "ball."). Returns true when a parameter that
// rebuilds the cloth was committed.
bool paramWidgets(Settings& settings, std::string_view prefix, bool allowUnsafe);

// All parameters, one collapsing header per group ("time", "material", ...). Same return value.
bool parameterGroups(Settings& settings, bool allowUnsafe);

} // namespace clothtear::app
