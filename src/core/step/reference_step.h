// What the two reference integrators (implicit_euler.h, xpbd.h) read for one sub-step.
// integrate_reference.cpp fills it; the integrators then move every free particle and leave pinned ones alone.
//
// Unlike the explicit integrators these see each spring's full stiffness: the stability guard
// (springs.cpp) exists only because explicit integration of a stiff spring explodes, and
// both references are stable at any step.
#pragma once
#include "clothtear/cloth.h"
#include "clothtear/kes.h"

#include <span>

namespace clothtear {

// One kind of spring with its material constants per unit weight: k = stiffness * weight (N/m),
// kd = damping * weight (N s/m), as in the explicit spring phase.
struct SpringKind {
    std::span<const Spring> springs;
    float stiffness; // N/m
    float damping;   // N s/m
};

struct ReferenceStepInput {
    float dt;                    // s
    Vec3 gravity;                // m/s^2
    float dragPerMass;           // 1/s: air drag a = -dragPerMass v (physical model)
    float keep;                  // Keserica air model: fraction of velocity kept per sub-step (1 otherwise)
    SpringKind kinds[2];         // structural, bend-shear
    std::span<const Vec3> force; // N per particle from other phases (wind); empty: none
    // material.model = kes, implicit Euler: the structural springs (kinds[0]; its stiffness unused)
    // follow the law, F = T(e) width up to kesStrainRange and its tangent beyond
    // (kesTensionInRange), and the hinges' forces (in `force`) bring their Jacobians.
    const KesLaw* kes = nullptr;
    double kesRange = 0;                  // strain
    std::span<const HingeTangent> hinges; // kes: every hinge linearized (kes.h)
};

} // namespace clothtear
