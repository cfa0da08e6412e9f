// Times one phase of the step into the profile; the scope reads like the algorithm in substep().
#pragma once
#include "clothtear/world.h"

#include <chrono>

namespace clothtear {

class PhaseTimer {
public:
    PhaseTimer(StepProfile& profile, Phase phase) : profile_(profile), phase_(phase), start_(Clock::now()) {}
    ~PhaseTimer() {
        profile_.ms[int(phase_)] += std::chrono::duration<double, std::milli>(Clock::now() - start_).count();
        profile_.runs[int(phase_)]++;
    }
    PhaseTimer(const PhaseTimer&) = delete;
    PhaseTimer& operator=(const PhaseTimer&) = delete;

private:
    using Clock = std::chrono::steady_clock;
    StepProfile& profile_;
    Phase phase_;
    Clock::time_point start_;
};

} // namespace clothtear
