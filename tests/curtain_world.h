// The built-in `curtain` scene at n x n particles, loaded as the app loads it (shared by the core
// and app tests that start from a plain curtain).
#pragma once
#include "clothtear/scenes.h"
#include "clothtear/world.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace clothtear::test {

inline World curtainWorld(int n) {
    World w;
    const std::string r = std::to_string(n);
    const std::vector<std::string> sets{"cloth.resolution_x=" + r, "cloth.resolution_y=" + r};
    EXPECT_EQ(loadScene(w, "curtain", sets), "");
    return w;
}

} // namespace clothtear::test
