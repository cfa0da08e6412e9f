// Sleep: a cloth at rest is not simulated until something can move it (sleep.cpp).
#pragma once
#include "step_state.h"

namespace clothtear {

// Before a frame: asleep and nothing can touch the cloth this frame? (Wakes it otherwise.)
bool stayAsleep(World& world, StepState& state);
// After a frame: at rest long enough to fall asleep?
void updateSleep(World& world, StepState& state);

} // namespace clothtear
