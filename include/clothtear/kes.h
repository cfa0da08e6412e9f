// The KES material law of Tagawa, Hayashi, Kijima, "Dynamic Cloth Simulation and its Evaluation
// Experiments in Vacuum", TVRSJ 8(3), 2003 (docs/kes-material.md says what was read from the damaged
// text and what was assumed): material.model = kes.
//
//   tension     per unit width, a polynomial of the strain fitted to KES-FB1 (Fig. 8(a)), applied on
//               each structural spring as F = T(e) x width along it (Eq. 1)
//   bending     moment per unit width against curvature, the hysteretic "rate model" fitted to
//               KES-FB2 (Eq. 3a/3b, Eq. 4, Fig. 8(b)), on a hinge per interior edge (the two
//               triangles of a bend-shear spring) with a per-hinge memory of the last reversal
//
// Units: the settings hold the coefficients as KES prints them (gf/cm, %, gf cm/cm, cm); kesLawSI
// converts them, in this one place, to SI (N/m, strain, N, m). Everything below is in SI.
// Pure functions: unit-tested without a world (tests/test_kes.cpp).
#pragma once
#include "clothtear/cloth.h"
#include "clothtear/settings.h"

#include <cstdint>
#include <vector>

namespace clothtear {

inline constexpr double kGramForce = 9.80665e-3; // N
inline constexpr double kCentimetre = 1e-2;      // m

struct KesLaw {
    // T(e) = sum_i c[i] e^i, e the strain (not percent), T in N/m; c[0] = 0.
    double c[5] = {0, 0, 0, 0, 0};
    double D = 0;     // N m      bending rigidity per unit width (moment per width per curvature)
    double D1 = 0;    // N        hysteresis moment per unit width
    double alpha = 0; // m        saturation length of the hysteresis after a reversal
    double reversal = 0; // 1/m   how far back from its extreme K must come for a reversal to count
};

// The settings' coefficients in SI: gf/cm -> N/m is x 0.980665; e in % -> strain is e = 100 s, so the
// coefficient of %^i gains 100^i; gf cm^2/cm -> N m is x 9.80665e-5; gf cm/cm -> N is x 9.80665e-3;
// cm -> m is x 0.01.
KesLaw kesLawSI(const MaterialSettings& m);

// Tension per unit width, N/m, at strain e. Tagawa's polynomial is measured in extension only; a
// compressed spring is given the mirror image, T(-e) = -T(e) (docs/kes-material.md: cloth buckles
// rather than compresses; the mirror keeps the mesh from collapsing and the force odd in e).
double kesTension(const KesLaw& law, double strain);
// The law as the step applies it: T(e) up to |e| = strainRange (kesStrainRange: the strains the
// guard's stable step covers), continued beyond it with its tangent there, so no spring is ever
// stiffer than the guard assumed. A spring pulled past the length limit (the tension scene's clamps
// drag the cloth to its tear threshold, 35 %, where T' is 32 x T'(10 %)) stays stable.
double kesTensionInRange(const KesLaw& law, double strain, double strainRange);
// dT/de, N/m per unit strain (even in e).
double kesTangent(const KesLaw& law, double strain);
// The largest tangent on [0, strainMax]: the stability guard's stiffness (coefficients are >= 0, so
// the tangent grows with |e| and this is kesTangent(strainMax); also > 0 when T'(0) = 0).
double kesMaxTangent(const KesLaw& law, double strainMax);

// The tangent the step applies at strain e: kesTangent up to |e| = strainRange, kesTangent(strainRange)
// beyond (the slope of kesTensionInRange).
double kesTangentInRange(const KesLaw& law, double strain, double strainRange);

// ---- forward Euler and the law ------------------------------------------------------------------
//
// Forward Euler multiplies the energy of a mode (angular frequency omega, damping rate g) by
// 1 - g dt + (omega dt)^2 a step: stable only while g > omega^2 dt, i.e. dt < kd / k per spring.
// The law's tangent makes material.stretch_damping a billion times too small for that, and the
// hinges have no damping (docs/kes-material.md, "Forward Euler"). With forward Euler the kes
// springs and hinges therefore get Rayleigh damping C = beta K_t, beta = kKesForwardEulerDamping dt,
// K_t the law's tangent where each spring and hinge is now: a mode of the linearized law then has
// g = beta omega^2 and its energy factor is 1 - (omega dt)^2 (implicit Euler's own numerical
// damping, to first order) as long as omega dt <= 1, which the guard keeps (kesGuardWeight). It
// vanishes with dt: forward Euler still converges to the undamped law.
inline constexpr double kKesForwardEulerDamping = 2.0; // beta / dt
// The Rayleigh time beta (s) the step applies at sub-step dt: kKesForwardEulerDamping dt with
// forward Euler and material.model = kes, else 0.
double kesRayleighTime(const Settings& settings, double dt);
// How many times its tangent the stability guard counts a kes spring or hinge: 1, or with forward
// Euler 1 + 2 kKesForwardEulerDamping = 5: the Rayleigh damping adds dt (beta k) = 2 dt^2 k to a
// spring's share 0.5 dt^2 k of the guard's sum (stability.cpp), 2.5 dt^2 k = 0.5 dt^2 (5 k); the
// guard's step then has (omega dt)^2 <= 0.8.
double kesGuardWeight(const Settings& settings);

// The strains the step lets a structural spring reach, over which the stability guard takes the
// law's largest tangent: limit.max_stretch with the length limit on (it pulls longer springs back
// each sub-step), else the tear threshold with tearing on, else 0.5.
double kesStrainRange(const Settings& settings);

// The memory of one hinge, BendMemory, is kept with the cloth (cloth.h: Cloth::bendMemory).

// The rate model (Tagawa Eq. 3a/3b): on the branch started at (K_r, M_r) in direction s,
//   M(K) = M_r + D (K - K_r) + s D1 (1 - exp(-alpha |K - K_r|)).
double kesMomentOnBranch(const KesLaw& law, const BendMemory& mem, double curvature);
// Moves the memory to curvature K and returns M(K), N (moment per unit width). Past the branch's
// extreme K_x (in its direction) the branch goes on and K_x follows; behind it, M is the branch a
// reversal at K_x would start (continuous at K_x), but the memory commits to it (K_r, M_r = K_x,
// M(K_x), the direction flips) only once K is back by more than law.reversal. Until then a return
// past K_x continues the old branch: a small back-and-forth retraces one curve and loses nothing,
// and the large loop forms as if it had not happened. With law.reversal = 0 every reversal counts
// at once (the plain rate model). Large cycles follow exactly the same M(K) either way.
//
//   M |          . old branch, on past K_x
//     |       .*  K_x: the extreme
//     |     .  /
//     |   .   /   the reversal's branch: tentative within `reversal` of K_x, committed beyond
//     +----------------- K
// `slope`, when not null, receives dM/dK of the branch M(K) was taken from (kesSlopeOnBranch).
double kesBendAdvance(const KesLaw& law, BendMemory& mem, double curvature, double* slope = nullptr);
// The slope dM/dK (N m) of the branch (K_r, M_r, s) at K: D + alpha D1 exp(-alpha |K - K_r|) on a
// branch K moves away from its start along (kesBendAdvance returns that branch's slope).
double kesSlopeOnBranch(const KesLaw& law, const BendMemory& mem, double curvature);
// Largest slope dM/dK of the law (right after a reversal): D + alpha D1, N m.
double kesMaxBendSlope(const KesLaw& law);
// Energy lost per unit area in one closed cycle K: -Km -> Km -> -Km on the steady loop, J/m^2:
//   D1 (2 Km (1 + exp(-2 alpha Km)) - 2 (1 - exp(-2 alpha Km)) / alpha)
// (the loop's area: the loading branch from (-Km, -M*) minus the unloading one from (Km, M*),
// with M* = D Km + D1 (1 - exp(-2 alpha Km)) / 2, Tagawa Eq. 4).
double kesLoopEnergyPerArea(const KesLaw& law, double maxCurvature);

// ---- the hinge (dihedral angle) of one bend-shear spring ----------------------------------------
//
//            c                 The bend-shear spring b joins the opposite corners c and d of the
//           / \                two triangles across edge (a, e) (Onal 3.1.2). The hinge's angle
//          /   \               theta is the dihedral angle between them (0 flat, signed), its
//         a-----e              curvature K = theta / L with L = (h_c + h_d) / 2 the rest heights'
//          \   /               mean (rest area of both triangles / rest edge length), and its torque
//           \ /                tau = M(K) w with w the rest edge length: the energy of a strip bent
//            d                 at K, w L int M dK, is that of a continuum of width w and length L
//                              (exact for a grid bent about either axis; docs/kes-material.md).
struct HingeGeometry {
    Index c, d, a, e;   // corners: c, d opposite, (a, e) the edge
    double width;       // m   rest edge length
    double length;      // m   L above
    double height;      // m   the smaller rest height of c or d over the edge
};
HingeGeometry hingeOf(const Cloth& cloth, Index bend);

// The hinge's stiffness as the stability guard counts it on each of its corners (N/m): the torque
// changes by S w / L per radian (S = kesMaxBendSlope) and a corner moving by x turns the hinge by
// about x / height; a Gershgorin row over the four corners' gradients (each about 1 / height) sums
// to 4 S w / (L height^2), half of which enters the guard's sum as a spring's k does (2 k per row).
double kesHingeStiffness(const KesLaw& law, const HingeGeometry& hinge);

// Signed dihedral angle (rad) of corners (c, d) across edge (a, e), and its gradient with respect to
// the four positions (Bridson et al. 2003, "Simulation of clothing with folds and wrinkles"): the
// gradients sum to zero and exert no torque. Returns false for a degenerate hinge (a zero-area side).
bool dihedralAngle(const Vec3& c, const Vec3& d, const Vec3& a, const Vec3& e, double& theta, Vec3d grad[4]);

// One hinge linearized for implicit Euler: its corners (c, d, a, e), the gradient of its angle and
// the stiffness dtau/dtheta = S w / L (N m per radian) its forces' Jacobian takes, without the term
// tau d^2 theta / dx^2 (Gauss-Newton: positive semi-definite): -dtau/dtheta grad_i grad_j^T.
// S is the law's largest slope D + alpha D1 (kesMaxBendSlope), not the slope of the branch the hinge
// is on: a reversal within the step makes the slope jump to it (x 25 from D with Tagawa's values).
// With the branch's slope, the vacuum swing at 10 implicit sub-steps a frame zig-zagged (374
// reversals per hinge per second beyond 0.3 1/m, the swing alone makes 5): no hysteresis, the
// period of D1 = 0 (0.502 s for 0.414); with the largest, 3 a second and 0.418 s
// (docs/kes-material.md, "Implicit Euler").
struct HingeTangent {
    Index p[4];
    Vec3d grad[4];   // 1/m
    double stiffness; // N m
};

// How the step applies the hinges in one sub-step (the defaults: forces only, as the tests call it).
struct HingeStep {
    // > 0 (s): the stability guard's cap, as on springs (spring_caps.h): a hinge whose stiffness
    // (kesHingeStiffness) x capWeight times its corners' inverse masses times capDt^2 is over 1/3
    // has its torque scaled down to meet it.
    double capDt = 0;
    double capWeight = 1; // kesGuardWeight
    // > 0 (s): Rayleigh damping, a torque -rayleigh x dtau/dtheta x dtheta/dt (kesRayleighTime).
    double rayleigh = 0;
    std::vector<HingeTangent>* tangents = nullptr; // when not null: every hinge's HingeTangent
};

// Bending forces of the material model on every particle, added to `force` (N; sized to the
// particles): kes, the hinges with their memory advanced to the current curvatures (memory sized to
// the bends, a new one starts at rest); linear, the bend-shear springs' Hooke forces without damping.
// `moment`, when not null, receives each hinge's M (N, per unit width) and curvature (1/m) in pairs.
void materialBendForces(const Cloth& cloth, const MaterialSettings& m, std::vector<BendMemory>& memory,
                        std::vector<Vec3d>& force, std::vector<double>* moment = nullptr,
                        const HingeStep& step = {});

} // namespace clothtear
