// Hems (issue 13, goal 3): what the pin mode pins is a hem, stronger than the cloth by
// tear.seam_strength, so a load that tears the cloth tears it below the hem, not off its pins.
#include "clothtear/scenes.h"
#include "clothtear/world.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace clothtear;

namespace {

struct FirstTears {
    int tears = 0;
    int onHem = 0;   // of the first tears, those of springs touching the hem row
    int checked = 0; // how many first tears were looked at
};

// The curtain's bottom row clamped by its hem and pulled straight down at 0.6 m/s: a tensile test of
// the hanging cloth between two hems. Looks at the first `look` tears.
FirstTears pullBottomDown(int n, float seam, float width, int look) {
    World w;
    const std::string res = std::to_string(n);
    EXPECT_EQ(loadScene(w, "curtain",
                        std::vector<std::string>{"cloth.resolution_x=" + res, "cloth.resolution_y=" + res,
                                                 "cloth.width=" + std::to_string(width),
                                                 "tear.seam_strength=" + std::to_string(seam)}),
              "");
    const double bottom = -0.5 * w.settings.cloth.height, top = 0.5 * w.settings.cloth.height;
    const double spacing = w.settings.cloth.height / (n - 1);
    Driver d{{}, Vec3(0.f, -0.6f, 0.f)};
    for (Index p = 0; p < w.cloth.particleCount(); ++p)
        if (w.cloth.rest[p].y() < bottom + 1e-6) {
            w.cloth.setPinned(p, true);
            w.cloth.flags[p] |= kHem; // clamped by its hem too
            d.particles.push_back(p);
        }
    w.drivers.push_back(d);
    for (int f = 0; f < 150 && int(w.tearLog.total()) < look; ++f) w.step();
    FirstTears out;
    out.tears = int(w.tearLog.total());
    for (const TearEvent& e : w.tearLog.events) {
        if (out.checked == look) break;
        ++out.checked;
        // A tear event sits at the torn spring's middle (basic) or its tip particle: within half a
        // spacing of the top row is a spring touching the hem.
        if (e.restPos.y() > top - 0.75 * spacing || e.restPos.y() < bottom + 0.75 * spacing) ++out.onHem;
    }
    return out;
}

} // namespace

// The strain gathers next to the moving clamp. With the hem as strong as the cloth (seam 1) some of
// the first tears are the hem's own springs (on the 2 m cloth): the cloth comes off its clamp. At the default seam
// strength none are: the cloth tears rows away from its hems. Two resolutions, two widths.
TEST(Hems, PullingTheHangingClothTearsItBelowItsHem) {
    EXPECT_GE(Settings{}.tear.seamStrength, 2.f) << "the default hem is well above the cloth";
    int weakHemTears = 0;
    for (int n : {24, 48})
        for (float width : {2.f, 1.f}) {
            const std::string what = std::to_string(n) + " a side, " + std::to_string(width) + " m wide";
            const FirstTears weak = pullBottomDown(n, 1.f, width, 10);
            const FirstTears hem = pullBottomDown(n, Settings{}.tear.seamStrength, width, 10);
            EXPECT_EQ(hem.checked, 10) << what << ": the load tears the cloth";
            EXPECT_EQ(hem.onHem, 0) << what << ": no tear at a hem";
            weakHemTears += weak.onHem;
        }
    EXPECT_GT(weakHemTears, 0) << "a hem as weak as the cloth tears somewhere (the test sees hem tears)";
}
