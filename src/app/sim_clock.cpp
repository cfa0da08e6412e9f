// The fixed-step accumulator.
#include "sim_clock.h"

#include <algorithm>
#include <cmath>

namespace clothtear::app {

int SimClock::advance(double realSeconds, double frameDt) {
    if (!(frameDt > 0.0)) return 0;
    accumulator += std::clamp(realSeconds, 0.0, 0.25);
    int due = int(std::floor(accumulator / frameDt));
    int cap = maxStepsPerFrame;
    if (stepCostMs > 0.0) cap = std::clamp(int(frameBudgetMs / stepCostMs), 1, maxStepsPerFrame);
    slowedDown = due > cap;
    if (slowedDown) {
        due = cap;
        accumulator = std::fmod(accumulator, frameDt); // drop what cannot be simulated in time
    } else {
        accumulator -= due * frameDt;
    }
    return due;
}

void SimClock::reportStepCost(double ms) {
    stepCostMs = stepCostMs <= 0.0 ? ms : 0.8 * stepCostMs + 0.2 * ms;
    stepMsTotal += ms;
    ++stepsTimed;
}

} // namespace clothtear::app
