// The phases of a sub-step, in the order step.cpp runs them, each a function of the step context,
// the cloth and the step state (docs/architecture.md lists what each reads and writes).
#pragma once
#include "step_context.h"
#include "step_state.h"

namespace clothtear {

// springs.cpp: sizes the per-thread force buffers (gravity and air act in the integrator).
void phaseForces(const StepContext& ctx, Cloth& cloth, StepState& state);
// springs.cpp: structural and bend-shear spring forces into the force buffers (explicit integrators).
void phaseSprings(const StepContext& ctx, Cloth& cloth, StepState& state);
// springs.cpp: packs the particles' x and v as the kernels read them and adds every spring's force,
// or the one term `terms` asks for (spring_groups.h), into the force buffers: the springs phase's
// pass, and with the damping taken implicitly (time.damping) its elastic pass and the integrator's
// damping pass (which reads the packed copy the elastic pass and the integrator left).
void springForcePass(const StepContext& ctx, Cloth& cloth, StepState& state, SpringTerms terms);
// material.model = kes (kes_forces.cpp): the tensile law on the structural springs and the
// hysteretic hinges, on one thread's buffer; advances the hinges' memory (Cloth::bendMemory).
void phaseSpringsKes(const StepContext& ctx, Cloth& cloth, StepState& state);
// The same forces summed into `force` (N per particle) for the reference integrators. With
// `implicit` (implicit Euler): the hinges' forces only, uncapped, each hinge linearized into
// *implicit (the solve applies the tensile law itself, implicit_euler.h).
void kesForces(const StepContext& ctx, Cloth& cloth, StepState& state, std::vector<Vec3>& force,
               std::vector<HingeTangent>* implicit = nullptr);
// Brings the spring cache up to date (springs.cpp); the strain scan and the ball broad phase read it.
void refreshSpringCache(const StepContext& ctx, const Cloth& cloth, StepState& state);
// wind.cpp: wind drag on every triangle into the force buffers.
void phaseWind(const StepContext& ctx, Cloth& cloth, StepState& state);
// integrate.cpp: semi-implicit Euler, forward Euler or Verlet; then the drivers move.
void phaseIntegrate(const StepContext& ctx, Cloth& cloth, StepState& state);
// integrate_reference.cpp: implicit Euler or XPBD, springs included; then the drivers move.
void phaseIntegrateReference(const StepContext& ctx, Cloth& cloth, StepState& state);
// collide_phase.cpp: balls move and push the cloth (before the limit); contacts listed.
void phaseCollide(const StepContext& ctx, Cloth& cloth, StepState& state);
// limit.cpp: strain scan (tear candidates), tethers, Provot length limiting.
void phaseLimit(const StepContext& ctx, Cloth& cloth, StepState& state);
// limit.cpp: does a driver move particles (the drag tool, the pull and tension scenes)?
bool driversMove(const std::vector<Driver>& drivers);
// collide_phase.cpp: balls give way where the limit held the cloth; the ground.
void phaseContact(const StepContext& ctx, Cloth& cloth, StepState& state);
// tear_phase.cpp: tears the candidates of the scan (the only topology change of the step).
void phaseTear(const StepContext& ctx, Cloth& cloth, StepState& state);
// tear_phase.cpp: a particle duplicated by a tear or a cut, (original, copy), keeps following
// whatever drove the original (World::cut uses it too).
void driversFollowCopies(std::vector<Driver>& drivers, const std::vector<std::pair<Index, Index>>& copies);

// integrate.cpp: kinematic drivers move their particles at constant velocity.
void moveDrivers(const StepContext& ctx, Cloth& cloth, StepState& state);

} // namespace clothtear
