// The parameter table: every parameter round-trips through its text form, and every kind of bad
// input gives one message that names the parameter and leaves the settings unchanged.
#include "clothtear/params.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <set>
#include <string>

using namespace clothtear;

namespace {

bool sameSettings(const Settings& a, const Settings& b) {
    for (const ParamInfo& p : allParams())
        if (getParam(a, p) != getParam(b, p))
            return false;
    return true;
}

// A value other than the default, inside the safe range, for each type.
double otherValue(const Settings& defaults, const ParamInfo& p, int variant) {
    const double d = getParam(defaults, p);
    switch (p.type) {
    case ParamType::Bool:
        return d != 0 ? 0 : 1;
    case ParamType::Enum: {
        int n = 0;
        while (p.enumNames[n])
            ++n;
        return double((int(d) + 1 + variant) % n);
    }
    case ParamType::Int: {
        const double v = std::round(p.safeMin + (p.safeMax - p.safeMin) * (variant ? 0.37 : 0.81));
        return v == d ? v + 1 : v;
    }
    case ParamType::Float:
        // Values with many significant digits: a text form that keeps only six would lose them.
        return p.safeMin + (p.safeMax - p.safeMin) * (variant ? 0.3719871 : 0.8123457);
    }
    return d;
}

TEST(Params, TableIsWellFormed) {
    std::set<std::string> names;
    const Settings defaults;
    for (const ParamInfo& p : allParams()) {
        EXPECT_TRUE(names.insert(p.name).second) << "duplicate " << p.name;
        EXPECT_EQ(findParam(p.name), &p);
        EXPECT_NE(std::strchr(p.name, '.'), nullptr) << p.name << " is not dotted";
        EXPECT_GT(std::strlen(p.help), 0u) << p.name;
        if (p.type == ParamType::Float || p.type == ParamType::Int) {
            EXPECT_LE(p.hardMin, p.safeMin) << p.name;
            EXPECT_LE(p.safeMin, p.safeMax) << p.name;
            EXPECT_LE(p.safeMax, p.hardMax) << p.name;
            const double d = getParam(defaults, p);
            EXPECT_TRUE(d >= p.hardMin && d <= p.hardMax)
                << p.name << " default " << d << " outside its valid range";
        }
        if (p.type == ParamType::Enum) {
            EXPECT_NE(p.enumNames, nullptr) << p.name;
        }
    }
    EXPECT_EQ(findParam("nope"), nullptr);
}

// Defaults and non-default values, through formatParamValue and back, exactly.
void expectRoundTrip(const Settings& source, const ParamInfo& p) {
    const std::string text = formatParamValue(source, p);
    Settings parsed;
    EXPECT_EQ(setParamFromString(parsed, p.name, text), "") << p.name << " = '" << text << "'";
    EXPECT_EQ(getParam(parsed, p), getParam(source, p))
        << p.name << ": '" << text << "' does not read back exactly";
    // The assignment form reads the same.
    Settings assigned;
    EXPECT_EQ(applyAssignment(assigned, std::string(p.name) + "=" + text), "") << p.name;
    EXPECT_EQ(getParam(assigned, p), getParam(source, p)) << p.name;
}

// Disabled: formatParamValue prints floats with six significant digits (std::ostream default),
// which does not read back as the same float for 1/60 (time.frame_dt's default reads back 18 ulps
// off) or for any value with more digits. Enable once floats are printed with
// std::numeric_limits<float>::max_digits10 (9) digits or std::to_chars' shortest form.
TEST(Params, EveryParameterRoundTripsExactly) {
    const Settings defaults;
    for (const ParamInfo& p : allParams()) {
        expectRoundTrip(defaults, p);
        for (int variant = 0; variant < 2; ++variant) {
            Settings s;
            setParamUnchecked(s, p, otherValue(defaults, p, variant));
            expectRoundTrip(s, p);
        }
    }
}

// What round-trips today: every bool, enum and int, and floats with at most four significant
// digits (every default except time.frame_dt = 1/60).
TEST(Params, EveryParameterRoundTripsShortValues) {
    const Settings defaults;
    for (const ParamInfo& p : allParams()) {
        for (int variant = 0; variant < 2; ++variant) {
            double v = otherValue(defaults, p, variant);
            if (p.type == ParamType::Float) {
                char text[32];
                std::snprintf(text, sizeof text, "%.4g", v);
                v = std::strtod(text, nullptr);
            }
            Settings s;
            setParamUnchecked(s, p, v);
            expectRoundTrip(s, p);
        }
        if (std::strcmp(p.name, "time.frame_dt") != 0)
            expectRoundTrip(defaults, p);
    }
}

TEST(Params, AcceptsTheDocumentedSpellings) {
    Settings s;
    EXPECT_EQ(setParamFromString(s, "limit.enabled", "off"), "");
    EXPECT_FALSE(s.limit.enabled);
    EXPECT_EQ(setParamFromString(s, "limit.enabled", "yes"), "");
    EXPECT_TRUE(s.limit.enabled);
    EXPECT_EQ(setParamFromString(s, "time.integrator", "verlet"), "");
    EXPECT_EQ(s.time.integrator, Integrator::Verlet);
    EXPECT_EQ(setParamFromString(s, "time.integrator", "1"), "");
    EXPECT_EQ(s.time.integrator, Integrator::ForwardEuler);
    EXPECT_EQ(applyAssignment(s, " material.density = 0.5 "), "");
    EXPECT_FLOAT_EQ(s.material.density, 0.5f);
    EXPECT_EQ(applyAssignment(s, "cloth.resolution_x=64"), "");
    EXPECT_EQ(s.cloth.resolutionX, 64);
}

// Each error names the parameter (or the whole assignment) and leaves the settings unchanged.
TEST(Params, BadInputGivesAMessageNamingTheParameter) {
    struct Case {
        const char* assignment;
        const char* mustName; // what the message has to mention
        const char* mustSay;  // and a word saying what was wrong
    };
    const Case cases[] = {
        {"nope=1", "nope", "unknown"},
        {"material.density=-1", "material.density", "range"},
        {"material.density=1e9", "material.density", "range"},
        {"material.density=abc", "material.density", "not a number"},
        {"material.density=1.5x", "material.density", "not a number"},
        {"material.density=nan", "material.density", "not a number"},
        {"material.density=", "material.density", "empty"},
        {"cloth.resolution_x=2.5", "cloth.resolution_x", "integer"},
        {"limit.enabled=maybe", "limit.enabled", "boolean"},
        {"time.integrator=rk4", "time.integrator", "one of"},
        {"time.integrator=7", "time.integrator", "one of"},
        {"material.density", "material.density", "malformed"},
    };
    for (const Case& c : cases) {
        Settings s;
        const std::string err = applyAssignment(s, c.assignment);
        EXPECT_NE(err.find(c.mustName), std::string::npos) << c.assignment << " -> '" << err << "'";
        EXPECT_NE(err.find(c.mustSay), std::string::npos) << c.assignment << " -> '" << err << "'";
        EXPECT_TRUE(sameSettings(s, Settings{})) << c.assignment << " changed the settings";
    }
    // The range message gives the range and the unit.
    Settings s;
    const std::string err = setParamFromString(s, "material.density", "-1");
    EXPECT_NE(err.find("kg/m^2"), std::string::npos) << err;
}

TEST(Params, MarkdownListsEveryParameter) {
    const std::string md = paramsMarkdown();
    for (const ParamInfo& p : allParams())
        EXPECT_NE(md.find(std::string("`") + p.name + "`"), std::string::npos) << p.name;
}

} // namespace
