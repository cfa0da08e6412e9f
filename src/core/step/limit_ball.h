// The length limit where a ball stretches the cloth (limit.cpp runs these before its passes, and its
// strain scan reads the gauge): the fabric a ball stretches beyond its contacts, the tension of the
// springs held past the tear threshold under a ball, and the mean strain of a gauge-long line of
// springs, which a spring shorter than tear.gauge_length tears by where no hand pulls
// (bench/README.md, "The fabric a ball stretches" and "A ball tears by metres of stretch").
#pragma once
#include "clothtear/cloth.h"
#include "step_context.h"
#include "step_state.h"

namespace clothtear {

// Marks kTouched, for this sub-step's limit, the particles within collision.stretch_band (rest
// distance along the structural springs) of a ball's contact triangles (StepState::stretchBand).
void markStretchBand(const StepContext& ctx, Cloth& cloth, StepState& state);

// Takes back the elastic force past the tear threshold of the springs under a ball shorter than
// tear.gauge_length (their tension stops growing at the threshold's).
void capTensionUnderBall(const StepContext& ctx, Cloth& cloth, StepState& state);

// The mean strain of the straightest line of structural springs through spring s, `gauge` long at
// rest (shorter where it ends at a border or a tear).
float gaugeStrain(const LimitCache& C, const Cloth& cloth, Index s, float gauge);

} // namespace clothtear
