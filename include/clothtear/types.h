// Basic vector and index types shared by the whole core.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry> // cross products
#include <cstdint>
#include <string>
#include <utility>

namespace clothtear {

using Vec3 = Eigen::Vector3f;  // live state (positions, velocities, forces): float
using Vec3d = Eigen::Vector3d; // rest data (rest positions, areas): double, so sums stay exact to 1e-9
using Vec2d = Eigen::Vector2d; // texture coordinates

using Index = uint32_t;
inline constexpr Index kNone = 0xffffffffu;

// Errors as values at the edges (loaders, parsers): either a value or one message.
template <class T> struct Result {
    T value{};
    std::string error; // empty on success; "file:line: what was wrong" style otherwise
    bool ok() const { return error.empty(); }
    static Result failure(std::string message) {
        Result r;
        r.error = std::move(message);
        return r;
    }
};

} // namespace clothtear
