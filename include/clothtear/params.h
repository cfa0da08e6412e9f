// The parameter table: one entry per field of Settings (settings.h), with name, unit, ranges and help.
// Everything that reads or writes parameters by name (--set, the ImGui panel, docs, validation) goes
// through this table, so a parameter is declared exactly once.
#pragma once
#include "clothtear/settings.h"
#include "clothtear/types.h"

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace clothtear {

enum class ParamType { Float, Int, Bool, Enum };

struct ParamInfo {
    const char* name;   // dotted name, e.g. "material.density"
    ParamType type;
    size_t offset;      // byte offset of the field inside Settings
    double safeMin, safeMax;   // range the UI offers by default; reachable values stay stable
    double hardMin, hardMax;   // range accepted at all (with "allow unsafe values")
    const char* unit;   // "kg/m^2", "" for counts/flags
    const char* help;   // one line for tooltips and docs
    const char* const* enumNames; // null-terminated list for Enum
    bool rebuildsCloth; // changing it rebuilds the cloth mesh
};

std::span<const ParamInfo> allParams();
const ParamInfo* findParam(std::string_view name);

// Numeric access (enums and bools as integers).
double getParam(const Settings& s, const ParamInfo& p);
void setParamUnchecked(Settings& s, const ParamInfo& p, double value);

// Parses "value" for parameter "name" (numbers, true/false/on/off, enum names) and checks the hard range.
// On error returns a message naming the parameter and what was wrong; the settings are left unchanged.
std::string setParamFromString(Settings& s, std::string_view name, std::string_view value);
// Parses "key=value".
std::string applyAssignment(Settings& s, std::string_view assignment);

// User text quoted in a message: control bytes as \xNN, so the message stays one line, and long
// text cut with "...". Parsers of parameters and config files use it for what they echo.
std::string shownInMessage(std::string_view text);

std::string formatParamValue(const Settings& s, const ParamInfo& p);
// Markdown table of every parameter (used to generate docs/parameters.md).
std::string paramsMarkdown();

} // namespace clothtear
