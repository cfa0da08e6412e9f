// The parameter table. Each row: name, type, field, safe range, hard range, unit, help.
#include "clothtear/params.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>

namespace clothtear {
namespace {

const char* const kIntegratorNames[] = {"semi-implicit-euler", "forward-euler", "verlet", "implicit-euler", "xpbd",
                                          nullptr};
const char* const kAirNames[] = {"drag", "keserica", nullptr};
const char* const kDampingNames[] = {"explicit", "implicit", "auto", nullptr};
const char* const kLimitSolverNames[] = {"gauss-seidel", "jacobi", nullptr};
const char* const kMaterialNames[] = {"linear", "kes", nullptr};
const char* const kMeshNames[] = {"grid", "irregular", "obj", nullptr};
const char* const kPinNames[] = {"none", "top", "corners", "sides", "left", nullptr};

#define CT_F(name, field, smin, smax, hmin, hmax, unit, help, rebuild)                                      \
    ParamInfo{name, ParamType::Float, offsetof(Settings, field), smin, smax, hmin, hmax, unit, help, nullptr, rebuild}
#define CT_I(name, field, smin, smax, hmin, hmax, unit, help, rebuild)                                      \
    ParamInfo{name, ParamType::Int, offsetof(Settings, field), smin, smax, hmin, hmax, unit, help, nullptr, rebuild}
#define CT_B(name, field, help, rebuild)                                                                    \
    ParamInfo{name, ParamType::Bool, offsetof(Settings, field), 0, 1, 0, 1, "", help, nullptr, rebuild}
#define CT_E(name, field, names, help, rebuild)                                                             \
    ParamInfo{name, ParamType::Enum, offsetof(Settings, field), 0, 0, 0, 0, "", help, names, rebuild}

const ParamInfo kParams[] = {
    CT_F("time.frame_dt", time.frameDt, 1.0 / 240, 1.0 / 20, 1e-5, 0.1, "s", "Simulated time per frame", false),
    CT_I("time.substeps", time.substeps, 1, 200, 1, 2000, "", "Sub-steps per frame (sub-step dt = frame_dt / substeps)", false),
    CT_E("time.integrator", time.integrator, kIntegratorNames, "Integration method (implicit-euler, xpbd: references, stable at any step, no stability guard)", false),
    CT_B("time.stability_guard", time.stabilityGuard, "Explicit integrators: raise the sub-steps (up to time.max_substeps) to the stable step estimated from the stiffest spring on the lightest particle, and cap each spring still too stiff (off: unsafe on purpose)", false),
    CT_I("time.max_substeps", time.maxSubsteps, 1, 400, 1, 2000, "", "Stability guard: most sub-steps per frame it may take for the material's stable step (beyond it, springs are capped; at most time.substeps: it only caps)", false),
    CT_E("time.damping", time.damping, kDampingNames, "Semi-implicit Euler, linear material: the springs' damping explicit, implicit (stable at any step, so the guard's step follows the stiffness alone; a second spring pass) or auto (implicit where explicit damping would make the guard soften the cloth, or where its sub-steps cost less)", false),
    CT_F("time.cg_tolerance", time.cgTolerance, 1e-8, 1e-2, 1e-10, 0.1, "", "Implicit Euler: relative residual at which the conjugate-gradient solve stops", false),
    CT_I("time.cg_max_iterations", time.cgMaxIterations, 10, 1000, 1, 100000, "", "Implicit Euler: most conjugate-gradient iterations per sub-step", false),
    CT_F("time.verlet_friction", time.verletFriction, 0, 0.2, 0, 1, "", "Verlet: fraction of velocity lost per step (Keserica f)", false),

    CT_F("material.density", material.density, 0.01, 5, 1e-4, 100, "kg/m^2", "Areal density, lumped to particles from rest triangle areas", false),
    CT_F("material.stretch_stiffness", material.stretchStiffness, 0, 200, 0, 1e6, "N/m", "Membrane stretch stiffness; per spring k = value * area / length^2", false),
    CT_F("material.stretch_damping", material.stretchDamping, 0, 2, 0, 1e4, "N s/m", "Damping along structural springs, same scaling", false),
    CT_F("material.bend_stiffness", material.bendStiffness, 0, 50, 0, 1e6, "N/m", "Bend-shear spring stiffness (Onal 3.1.2)", false),
    CT_F("material.bend_damping", material.bendDamping, 0, 0.5, 0, 1e4, "N s/m", "Bend-shear spring damping", false),
    CT_E("material.model", material.model, kMaterialNames, "Material law: linear (Hooke springs, the stiffness and damping above) or kes (Tagawa 2003: KES tensile polynomial on the structural springs, hysteretic bending hinges instead of the bend-shear springs; docs/kes-material.md)", false),
    CT_F("material.kes_t1", material.kesT1, 0, 100, 0, 1e5, "gf/cm per %", "kes: tension per unit width, coefficient of e (e: strain in %)", false),
    CT_F("material.kes_t2", material.kesT2, 0, 100, 0, 1e5, "gf/cm per %^2", "kes: tension per unit width, coefficient of e^2 (Tagawa Fig. 8(a): 8.5748)", false),
    CT_F("material.kes_t3", material.kesT3, 0, 10, 0, 1e4, "gf/cm per %^3", "kes: tension per unit width, coefficient of e^3", false),
    CT_F("material.kes_t4", material.kesT4, 0, 10, 0, 1e4, "gf/cm per %^4", "kes: tension per unit width, coefficient of e^4 (Tagawa Fig. 8(a): 0.1191)", false),
    CT_F("material.kes_bend_d", material.kesBendD, 0, 2, 0, 1000, "gf cm^2/cm", "kes: bending rigidity D (Tagawa Fig. 8(b): 0.12266)", false),
    CT_F("material.kes_bend_d1", material.kesBendD1, 0, 2, 0, 1000, "gf cm/cm", "kes: bending hysteresis D1, the loop's width at K = 0 (Tagawa Fig. 8(b): 0.1181)", false),
    CT_F("material.kes_bend_alpha", material.kesBendAlpha, 0.1, 200, 1e-3, 1e5, "cm", "kes: how fast the hysteresis saturates after a reversal, exp(-alpha abs(K - K_r)) (Tagawa Fig. 8(b): 24.94)", false),
    CT_F("material.kes_bend_reversal", material.kesBendReversal, 0, 2, 0, 1e4, "1/m", "kes: a reversal of the curvature starts a new hysteresis branch only once the curvature is back by this much from its extreme (smaller ones, a sub-step's jitter, leave the branch as it was; in 1/m, not cm^-1; docs/kes-material.md)", false),

    CT_E("air.model", air.model, kAirNames, "Air friction: physical drag, or Keserica's fixed fraction per step", false),
    CT_F("air.drag", air.dragCoefficient, 0, 5, 0, 1000, "kg/(m^2 s)", "Linear air drag per unit area: F = -c A v", false),
    CT_F("air.keserica_factor", air.kesericaFactor, 0, 0.5, 0, 1, "", "Keserica model: fraction of velocity removed per sub-step", false),

    CT_F("gravity.x", gravity.x, -30, 30, -1000, 1000, "m/s^2", "Gravity, x component", false),
    CT_F("gravity.y", gravity.y, -30, 30, -1000, 1000, "m/s^2", "Gravity, y component (up is +y)", false),
    CT_F("gravity.z", gravity.z, -30, 30, -1000, 1000, "m/s^2", "Gravity, z component", false),

    CT_B("limit.enabled", limit.enabled, "Provot length limiting after each sub-step", false),
    CT_F("limit.max_stretch", limit.maxStretch, 0.01, 0.5, 0.001, 10, "", "Springs longer than rest*(1+value) are pulled back", false),
    CT_I("limit.iterations", limit.iterations, 0, 50, 0, 1000, "", "Most passes of the length limit per sub-step with jacobi; gauss-seidel takes up to the larger of this and 4 x the cloth's depth in springs, an eighth of the depth while a driver (the drag tool, a scene's hand or clamp) moves particles, or the depth while a ball touches the cloth (passes stop when nothing is over the limit)", false),
    CT_F("limit.relaxation", limit.relaxation, 0.5, 1.8, 0.1, 2, "", "Over-relaxation of the limit's correction", false),
    CT_E("limit.solver", limit.solver, kLimitSolverNames, "How the limit's passes correct: gauss-seidel (in place, spring after spring: converges in far fewer passes) or jacobi (averaged)", false),

    CT_B("wind.enabled", wind.enabled, "Wind force on triangles", false),
    CT_F("wind.dir_x", wind.dirX, -1, 1, -1, 1, "", "Wind direction, x", false),
    CT_F("wind.dir_y", wind.dirY, -1, 1, -1, 1, "", "Wind direction, y", false),
    CT_F("wind.dir_z", wind.dirZ, -1, 1, -1, 1, "", "Wind direction, z", false),
    CT_F("wind.speed", wind.speed, 0, 30, 0, 1000, "m/s", "Mean wind speed", false),
    CT_F("wind.gust", wind.gust, 0, 1, 0, 10, "", "Gust amplitude relative to speed", false),
    CT_F("wind.gust_frequency", wind.gustFrequency, 0, 5, 0, 100, "Hz", "Gust frequency", false),
    CT_F("wind.drag", wind.dragCoefficient, 0, 5, 0, 1000, "kg/m^3", "Pressure coefficient: F = c A (n.v)|n.v| n", false),

    CT_B("collision.ground", collision.ground, "Ground plane", false),
    CT_F("collision.ground_height", collision.groundHeight, -20, 20, -1000, 1000, "m", "Height of the ground plane", false),
    CT_F("collision.friction", collision.friction, 0, 1, 0, 10, "", "Coulomb friction between cloth and colliders", false),
    CT_F("collision.thickness", collision.thickness, 0, 0.05, 0, 1, "m", "Gap kept between cloth and colliders", false),
    CT_F("collision.stretch_band", collision.stretchBand, 0, 0.5, 0, 100, "m", "Fabric within this distance (along the cloth, at rest) of a ball's contact may stretch past the limit like the contact itself (to the tear threshold, over tear.gauge_length): a ball stretches the same band of fabric at every resolution (at least the contact's own springs)", false),
    CT_B("collision.broad_phase", collision.broadPhase, "Ball phases test only the triangles of particles near each ball (off: every triangle; the same result, slower: what the broad phase saves, bench/README.md)", false),

    CT_B("tear.enabled", tear.enabled, "Tearing (strain scan and topology changes)", false),
    CT_F("tear.threshold", tear.threshold, 0.05, 3, 0.001, 100, "", "Strain at which a spring tears (basic tear)", false),
    CT_F("tear.seam_strength", tear.seamStrength, 1, 10, 1, 100, "x threshold", "Springs touching a pinned edge (the hem) tear at this multiple of tear.threshold, before any weak point", false),
    CT_F("tear.weak_threshold", tear.weakThreshold, 0.02, 3, 0.001, 100, "", "Strain at which a spring touching a weak point tears", false),
    CT_F("tear.one_point_threshold", tear.onePointThreshold, 0.02, 3, 0.001, 100, "", "Strain that separates a one-point connection", false),
    CT_F("tear.gauge_length", tear.gaugeLength, 0, 0.5, 0, 100, "m", "Length of fabric a tear's strain is measured over where no hand pulls: a spring shorter than this tears when the mean strain of a line of springs this long through it reaches tear.threshold (under a ball it may stretch that far, its tension capped at the threshold's; a longer spring tears by its own strain), so a ball tears by metres of stretch, not by the strain of the one ring of springs it pulls on, whose width is the mesh spacing", false),
    CT_F("tear.tip_radius", tear.tipRadius, 0, 2, 0, 100, "m", "A tear tip (weak point) runs on across the direction in which the fabric within this distance of it is stretched most (its tensile strain, by rest area), the same metres of cloth at every resolution; 0, or a pin or the hand that close: across the tense spring, as Onal 3.2.2", false),
    CT_I("tear.max_per_step", tear.maxPerStep, 1, 10000, 1, 1000000, "", "Cap on tears per sub-step", false),
    CT_B("tear.validate", tear.validate, "Validate every topology invariant after each tear (slow)", false),
    CT_B("check.finite", check.finite, "Check for NaN/Inf after every phase of every sub-step; the report names the phase and particle (on in Debug builds)", false),

    CT_B("sleep.enabled", sleep.enabled, "Stop simulating a cloth at rest until a ball, driver, wind, impulse or change of settings can move it", false),
    CT_F("sleep.speed", sleep.speed, 1e-5, 0.1, 1e-6, 1, "m/s", "Sleep: a cloth whose particles are all slower than this is at rest", false),
    CT_F("sleep.delay", sleep.delay, 0.1, 10, 0, 60, "s", "Sleep: how long the cloth must be at rest before it sleeps", false),

    CT_E("cloth.mesh", cloth.mesh, kMeshNames, "Mesh type", true),
    CT_I("cloth.resolution_x", cloth.resolutionX, 2, 256, 2, 2048, "", "Particles across", true),
    CT_I("cloth.resolution_y", cloth.resolutionY, 2, 256, 2, 2048, "", "Particles down", true),
    CT_F("cloth.width", cloth.width, 0.1, 20, 0.01, 1000, "m", "Cloth width", true),
    CT_F("cloth.height", cloth.height, 0.1, 20, 0.01, 1000, "m", "Cloth height", true),
    CT_F("cloth.jitter", cloth.jitter, 0, 0.4, 0, 0.45, "", "Irregular mesh: vertex jitter as a fraction of spacing", true),
    CT_I("cloth.seed", cloth.seed, 0, 1000000, 0, 2147483647, "", "Irregular mesh: random seed", true),
    CT_E("cloth.pin", cloth.pin, kPinNames, "Which particles are pinned", true),
    CT_F("cloth.tilt", cloth.tilt, -90, 90, -90, 90, "deg", "Rotation about the top edge (90 = horizontal)", true),

    CT_F("pull.angle", scene.pullAngle, -180, 180, -360, 360, "deg", "Pull scene: direction in the cloth plane, 0 = down", true),
    CT_F("pull.speed", scene.pullSpeed, 0, 5, 0, 100, "m/s", "Pull scene: speed of the hand (the particles within grab.radius of the bottom centre)", true),
    CT_F("tension.speed", scene.tensionSpeed, 0, 2, 0, 100, "m/s", "Tension scene: speed of each clamp", true),
    CT_B("tension.notch", scene.tensionNotch, "Tension scene: cut a short slit in the middle", true),
    CT_F("grab.radius", scene.grabRadius, 0, 1, 0, 10, "m",
         "The hand's size: a drag and the pull scene hold every particle within this rest distance of the grabbed one (0: one particle)",
         false),
    CT_F("swing.offset", scene.swingOffset, 0, 0.09, 0, 1, "m", "swing-vacuum scene: the free end's offset at release (the strip an arc below its clamp)", true),
    CT_F("impulse.spin", scene.impulseSpin, 0, 60, 0, 1000, "rad/s", "impulse-rotation scene: angular velocity the impulse gives the strip about its clamp", true),
    CT_F("ball.radius", scene.ballRadius, 0.05, 5, 0.001, 100, "m", "Radius of thrown balls", false),
    CT_F("ball.speed", scene.ballSpeed, 0, 30, 0, 1000, "m/s", "Speed of thrown balls", false),
    CT_F("ball.mass", scene.ballMass, 0.05, 100, 1e-4, 1e5, "kg", "Mass of thrown balls", false),
    CT_F("ball.height", scene.ballHeight, 0, 1, 0, 1, "", "Ball scenes: aim height as a fraction of the cloth height", true),
};

#undef CT_F
#undef CT_I
#undef CT_B
#undef CT_E

template <class T> T& field(Settings& s, const ParamInfo& p) {
    return *reinterpret_cast<T*>(reinterpret_cast<char*>(&s) + p.offset);
}
template <class T> const T& field(const Settings& s, const ParamInfo& p) {
    return *reinterpret_cast<const T*>(reinterpret_cast<const char*>(&s) + p.offset);
}

int enumCount(const ParamInfo& p) {
    int n = 0;
    while (p.enumNames[n]) ++n;
    return n;
}

std::string trim(std::string_view v) {
    while (!v.empty() && (v.front() == ' ' || v.front() == '\t')) v.remove_prefix(1);
    while (!v.empty() && (v.back() == ' ' || v.back() == '\t' || v.back() == '\r' || v.back() == '\n')) v.remove_suffix(1);
    return std::string(v);
}

std::string fmtDouble(double v) {
    std::ostringstream o;
    o.precision(9); // enough digits for a float to read back exactly
    o << v;
    return o.str();
}

} // namespace

std::span<const ParamInfo> allParams() { return kParams; }

// At most 60 characters, so one bad value cannot flood the terminal.
std::string shownInMessage(std::string_view v) {
    constexpr size_t kMax = 60;
    std::string out;
    for (size_t i = 0; i < v.size() && i < kMax; ++i) {
        const unsigned char c = static_cast<unsigned char>(v[i]);
        if (c < 0x20 || c == 0x7f) {
            char hex[8];
            std::snprintf(hex, sizeof hex, "\\x%02x", c);
            out += hex;
        } else {
            out += char(c);
        }
    }
    if (v.size() > kMax) out += "...";
    return out;
}

const ParamInfo* findParam(std::string_view name) {
    for (const ParamInfo& p : kParams)
        if (name == p.name) return &p;
    return nullptr;
}

double getParam(const Settings& s, const ParamInfo& p) {
    switch (p.type) {
    case ParamType::Float: return field<float>(s, p);
    case ParamType::Int: return field<int32_t>(s, p);
    case ParamType::Bool: return field<bool>(s, p) ? 1.0 : 0.0;
    case ParamType::Enum: return field<int32_t>(s, p);
    }
    return 0;
}

void setParamUnchecked(Settings& s, const ParamInfo& p, double value) {
    switch (p.type) {
    case ParamType::Float: field<float>(s, p) = static_cast<float>(value); break;
    case ParamType::Int: field<int32_t>(s, p) = static_cast<int32_t>(std::lround(value)); break;
    case ParamType::Bool: field<bool>(s, p) = value != 0.0; break;
    case ParamType::Enum: field<int32_t>(s, p) = static_cast<int32_t>(std::lround(value)); break;
    }
}

std::string setParamFromString(Settings& s, std::string_view name, std::string_view rawValue) {
    const ParamInfo* p = findParam(name);
    if (!p) return "unknown parameter '" + shownInMessage(name) + "' (see --list-params for the list)";
    const std::string value = trim(rawValue);
    if (value.empty()) return "parameter '" + std::string(name) + "': empty value";
    const std::string said = shownInMessage(value);
    if (p->type == ParamType::Bool) {
        if (value == "1" || value == "true" || value == "on" || value == "yes") field<bool>(s, *p) = true;
        else if (value == "0" || value == "false" || value == "off" || value == "no") field<bool>(s, *p) = false;
        else return "parameter '" + std::string(name) + "': '" + said + "' is not a boolean (use true/false, on/off, 1/0)";
        return {};
    }
    if (p->type == ParamType::Enum) {
        const int n = enumCount(*p);
        for (int i = 0; i < n; ++i)
            if (value == p->enumNames[i]) {
                field<int32_t>(s, *p) = i;
                return {};
            }
        int index = -1;
        auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), index);
        if (ec == std::errc() && ptr == value.data() + value.size() && index >= 0 && index < n) {
            field<int32_t>(s, *p) = index;
            return {};
        }
        std::string options;
        for (int i = 0; i < n; ++i) options += std::string(i ? ", " : "") + p->enumNames[i];
        return "parameter '" + std::string(name) + "': '" + said + "' is not one of: " + options;
    }
    double parsed = 0;
    auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), parsed);
    if (ec != std::errc() || ptr != value.data() + value.size() || !std::isfinite(parsed))
        return "parameter '" + std::string(name) + "': '" + said + "' is not a number";
    if (p->type == ParamType::Int && parsed != std::floor(parsed))
        return "parameter '" + std::string(name) + "': '" + said + "' is not an integer";
    // A float parameter is checked as it will be stored: 0.0999...9 rounds to the float 0.1, which is
    // within a range ending at 0.1 only when the bound is rounded alike (fuzz_set found it).
    double lo = p->hardMin, hi = p->hardMax;
    if (p->type == ParamType::Float) parsed = double(float(parsed)), lo = double(float(lo)), hi = double(float(hi));
    if (!(parsed >= lo && parsed <= hi))
        return "parameter '" + std::string(name) + "': " + said + " is outside the valid range [" +
               fmtDouble(p->hardMin) + ", " + fmtDouble(p->hardMax) + "]" + (p->unit[0] ? std::string(" ") + p->unit : "");
    setParamUnchecked(s, *p, parsed);
    return {};
}

std::string applyAssignment(Settings& s, std::string_view assignment) {
    const size_t eq = assignment.find('=');
    if (eq == std::string_view::npos)
        return "malformed assignment '" + shownInMessage(assignment) + "' (expected key=value)";
    return setParamFromString(s, trim(assignment.substr(0, eq)), assignment.substr(eq + 1));
}

std::string formatParamValue(const Settings& s, const ParamInfo& p) {
    switch (p.type) {
    case ParamType::Bool: return field<bool>(s, p) ? "true" : "false";
    case ParamType::Enum: {
        const int i = field<int32_t>(s, p);
        return (i >= 0 && i < enumCount(p)) ? p.enumNames[i] : std::to_string(i);
    }
    // All the digits of an integer: fmtDouble's nine significant ones print a seed of 2147483647 as
    // 2.14748365e+09, which reads back as another number (world files write every value this way).
    case ParamType::Int: return std::to_string(field<int32_t>(s, p));
    default: return fmtDouble(getParam(s, p));
    }
}

std::string paramsMarkdown() {
    const Settings defaults;
    std::ostringstream o;
    o << "| name | default | unit | safe range | valid range | rebuilds | description |\n";
    o << "|---|---|---|---|---|---|---|\n";
    for (const ParamInfo& p : kParams) {
        o << "| `" << p.name << "` | " << formatParamValue(defaults, p) << " | " << p.unit << " | ";
        if (p.type == ParamType::Float || p.type == ParamType::Int)
            o << "[" << p.safeMin << ", " << p.safeMax << "] | [" << p.hardMin << ", " << p.hardMax << "]";
        else if (p.type == ParamType::Enum) {
            for (int i = 0; p.enumNames[i]; ++i) o << (i ? ", " : "") << p.enumNames[i];
            o << " | same";
        } else
            o << "true/false | same";
        o << " | " << (p.rebuildsCloth ? "yes" : "") << " | " << p.help << " |\n";
    }
    return o.str();
}

} // namespace clothtear
