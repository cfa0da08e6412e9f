// --set harness: bytes as one "key=value". Accepted: the value is finite, inside the parameter's hard
// range, and its printed form reads back to the same bits. Refused: one line, settings untouched.
#include "harness.h"

#include "clothtear/params.h"

#include <cmath>
#include <cstring>

namespace clothtear::fuzz {
namespace {

bool sameBits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

std::string untouched(const Settings& s) {
    const Settings defaults;
    for (const ParamInfo& p : allParams())
        if (!sameBits(getParam(s, p), getParam(defaults, p)))
            return std::string("a refusal changed ") + p.name;
    return {};
}

} // namespace

std::string fuzzSet(std::string_view bytes) {
    Settings s;
    const std::string err = applyAssignment(s, bytes);
    if (!err.empty()) {
        if (err.find('\n') != std::string::npos)
            return "message is more than one line: " + err;
        return untouched(s);
    }
    const size_t eq = bytes.find('=');
    if (eq == std::string_view::npos)
        return "accepted an assignment without '='";
    std::string_view key = bytes.substr(0, eq);
    // The same blanks applyAssignment trims around a key.
    auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
    while (!key.empty() && blank(key.front()))
        key.remove_prefix(1);
    while (!key.empty() && blank(key.back()))
        key.remove_suffix(1);
    const ParamInfo* p = findParam(key);
    if (!p)
        return "accepted unknown parameter '" + std::string(key) + "'";
    const double value = getParam(s, *p);
    if (!std::isfinite(value))
        return std::string(p->name) + " took a non-finite value";
    // Float parameters are stored as float: their bounds as floats too (params.cpp checks so).
    const bool asFloat = p->type == ParamType::Float;
    const double lo = asFloat ? double(float(p->hardMin)) : p->hardMin, hi = asFloat ? double(float(p->hardMax)) : p->hardMax;
    if ((p->type == ParamType::Float || p->type == ParamType::Int) && (value < lo || value > hi))
        return std::string(p->name) + " took " + std::to_string(value) + ", outside its hard range";
    Settings again;
    if (std::string e = setParamFromString(again, p->name, formatParamValue(s, *p)); !e.empty())
        return std::string(p->name) + ": its printed value does not read back: " + e;
    if (!sameBits(getParam(again, *p), value))
        return std::string(p->name) + ": printed value '" + formatParamValue(s, *p) +
               "' reads back differently";
    return {};
}

} // namespace clothtear::fuzz
