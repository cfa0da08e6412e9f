// Which way a rip runs, from a JSON report's tear events: the principal axis of their rest positions
// in the cloth's x-y plane. Shared by the headless tear-scene tests and the window's drag tests.
#pragma once
#include <nlohmann/json.hpp>

#include <cmath>

struct TearAxis {
    double mx = 0, my = 0; // m, the mean rest position of the tear events
    double theta = 0;      // rad, the principal axis from the x axis, in [-pi/2, pi/2]
};

// `events` must not be empty.
inline TearAxis tearAxisOf(const nlohmann::json& events) {
    TearAxis a;
    for (const auto& e : events) a.mx += e["rest"][0].get<double>(), a.my += e["rest"][1].get<double>();
    a.mx /= double(events.size()), a.my /= double(events.size());
    double sxx = 0, syy = 0, sxy = 0;
    for (const auto& e : events) {
        const double dx = e["rest"][0].get<double>() - a.mx, dy = e["rest"][1].get<double>() - a.my;
        sxx += dx * dx, syy += dy * dy, sxy += dx * dy;
    }
    a.theta = 0.5 * std::atan2(2 * sxy, sxx - syy);
    return a;
}
