// Fixed-step simulation clock (an accumulator), independent of the display rate. When the simulation
// cannot keep up, the number of steps per displayed frame is capped from the measured step cost and the
// excess time is dropped: the simulation slows down instead of spiralling. Pure (no GL).
#pragma once

namespace clothtear::app {

struct SimClock {
    double accumulator = 0.0;    // s of real time not yet simulated
    double stepCostMs = 0.0;     // smoothed wall-clock cost of one world.step()
    double frameBudgetMs = 30.0; // ms of stepping allowed per displayed frame
    int maxStepsPerFrame = 4;    // hard cap
    bool slowedDown = false;     // the last advance() dropped time
    double stepMsTotal = 0.0;    // wall-clock ms of every step reported, for the report's mean
    unsigned long long stepsTimed = 0;

    // Adds realSeconds (clamped to 0.25 s, e.g. after a stall) and returns how many steps of frameDt to run.
    int advance(double realSeconds, double frameDt);
    // Reports how long one step took, to size the cap (and to the totals).
    void reportStepCost(double ms);
    void reset() { accumulator = 0.0, slowedDown = false; }
};

} // namespace clothtear::app
