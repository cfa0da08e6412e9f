// The cloth: particles, structural springs (triangle edges), bend-shear springs and triangles.
//
// Layout (data-oriented, index based, no pointer graph):
//   particles  : parallel arrays x, v, invMass (hot) and mass, rest, flags, particleTris (cold)
//   springs    : Spring {a, b, rest, weight} (hot) + SpringTopo {tri[2], bend} (cold), one per edge
//   bends      : Spring (hot) + owning edge index (cold), one per interior edge (Onal 3.1.2)
//   triangles  : Triangle {p[3], s[3], uv[3]} with s[i] the spring joining p[i] and p[(i+1)%3]
// Tearing appends particles (never removes them, so a particle index is a stable handle) and replaces
// springs and triangles in place or by swap-and-pop with the few back-references fixed up.
#pragma once
#include "clothtear/mesh.h"
#include "clothtear/types.h"

#include <array>
#include <vector>

namespace clothtear {

enum ParticleFlags : uint8_t {
    kPinned = 1u << 0, // never moved by forces, limiting or collisions (may be moved by a driver/tool)
    kWeak = 1u << 1,   // tip of a tear: springs touching it tear at the weak threshold (Onal 3.2.2)
    kHinge = 1u << 2,  // one-point connection: two parts of the cloth meet only here (Onal 3.2.3)
    kTouched = 1u << 3, // under a ball this sub-step (set by the collide phase, cleared by the contact phase;
                        // during the limit also the fabric within collision.stretch_band of it)
    kHem = 1u << 4,     // on an edge the pin mode pinned: springs touching it tear at tear.seam_strength x the
                        // threshold (a sewn hem stays strong when a tool unpins it)
    kAsleep = 1u << 5,  // in a torn piece that settled (step/piece_sleep.cpp): inverse mass 0 and no velocity
                        // until something can move it
};

// A spring as the hot loops see it. Per-spring constants come from the material at use:
//   k  = material stiffness * weight,  kd = material damping * weight,
//   weight = (rest area of the adjacent triangles) / rest^2   (resolution independence).
struct Spring {
    Index a, b;
    float rest;   // m
    float weight; // 1 (dimensionless: area / length^2)
};

struct SpringTopo {
    Index tri[2] = {kNone, kNone}; // adjacent triangles; tri[1] == kNone on a border or torn edge
    Index bend = kNone;            // bend-shear spring across this edge, if interior
};

struct Triangle {
    Index p[3];        // particles, counter-clockwise in UV space
    Index s[3];        // s[i] joins p[i] and p[(i+1) % 3]
    Vec2d uv[3];       // texture coordinates per corner (Onal 3.3)
    double restArea;   // m^2, from the particles' rest positions
};

// material.model = kes (clothtear/kes.h): the memory of one hinge (one per bend-shear spring,
// Cloth::bendMemory): the branch it is on, the reversal point the branch started from and how far
// along it the hinge has gone. A new hinge starts at the origin on the loading branch of the virgin
// curve M = D K + sign(K) D1 (1 - exp(-alpha |K|)).
struct BendMemory {
    float extremeK = 0;     // 1/m   the curvature furthest along the branch's direction so far: a
                            //       reversal counts once K is back from it by material.kes_bend_reversal
                            //       (with 0, the curvature at the last evaluation)
    float reversalK = 0;    // 1/m   where the current branch started
    float reversalM = 0;    // N     the moment per width there
    int32_t direction = 0;  // +1 loading (dK/dt > 0), -1 unloading, 0 not moved yet
};

struct Cloth {
    // ---- particles: hot
    std::vector<Vec3> x, v; // m, m/s
    std::vector<float> invMass; // 0 for pinned
    // ---- particles: cold
    std::vector<double> areaShare;  // m^2: one third of the rest area of each incident triangle
    std::vector<Vec3d> rest;        // rest-space position (material coordinates)
    std::vector<uint8_t> flags;     // ParticleFlags
    std::vector<std::vector<Index>> particleTris; // incident triangles
    // ---- springs
    std::vector<Spring> springs;
    std::vector<SpringTopo> springTopo;
    std::vector<Spring> bends;
    std::vector<Index> bendEdge; // structural spring this bend-shear spring crosses
    // kes only: per bend-shear spring, its hinge's memory (the hysteresis branch); empty until the
    // kes model first steps, then kept parallel to `bends` by every topology change (a new hinge
    // starts at rest). Saved with the world and in checkpoints; hashed when not empty.
    std::vector<BendMemory> bendMemory;
    // ---- triangles
    std::vector<Triangle> triangles;

    uint64_t topologyRevision = 0; // bumped on every structural change (renderers re-upload indices)
    // A new process-wide unique value whenever an inverse mass is set (pins, tears, density): the
    // step's caches follow it at once, and never take one cloth for another
    // (src/core/step/revisions.h). Every change of the topology (a tear's refreshAround, a deleted
    // piece, a cloth built or loaded) sets one too, so the history shares the topology's arrays
    // between checkpoints by it (history.cpp, Taker::keyed): code that changes them must end with
    // refreshInvMass of the particles it touched.
    uint64_t massRevision = 0;
    float density = 0.2f;          // kg/m^2 used for mass lumping
    // m. Springs shorter than this are not split again (a front that keeps halving the same corner
    // makes slivers of vanishing mass): the knife's floor; a basic tear's is minTearSplitRest. Set by
    // buildCloth to kMinSplitFraction of the mean structural rest length.
    float minSplitRest = 0.f;

    size_t particleCount() const { return x.size(); }
    double particleMass(Index p) const { return density * areaShare[p]; }
    bool pinned(Index p) const { return flags[p] & kPinned; }
    bool asleep(Index p) const { return flags[p] & kAsleep; }
    void setAsleep(Index p, bool on); // asleep: inverse mass 0 (like a pin) and velocity 0
    void setPinned(Index p, bool on);
    void setDensity(float density);
    void refreshInvMass(Index p);

    double totalMass() const;
    double totalRestArea() const;
    double totalUvArea() const;
};

// Springs down to this fraction of the mean rest length can be split (the knife's floor: three
// halvings of an original edge).
constexpr double kMinSplitFraction = 0.125;
// A basic tear halves springs down to this fraction of the mean rest length only: an edge of the
// mesh once, never its halves. On a grid of spacing h (mean about 1.14 h) rows and columns are
// 0.88 of the mean and diagonals 1.24, their halves 0.44 and 0.62, so the floor sits between the
// two groups with room on both sides; on a mesh of mixed sizes, edges under 0.7 of the mean tear
// only through weak points. Halving the halves at a tear front made slivers of 1/4 and 1/8 of a
// triangle hanging on one particle, which a one-point split then set loose (issue 13, no confetti:
// the drag script at 40 a side left a 1.6 cm^2 scrap with a floor of 0.5, which still let a
// diagonal's half be halved: with the tethers to the pins' span (tethers.h) the pull scene pulled
// sideways at 80 left a 0.0004 m^2 scrap that way). A shorter spring over its threshold is held
// by the limit like any other and the tear goes on through its weak points.
constexpr double kMinTearSplitFraction = 0.7;
// The mean structural rest length of the mesh as built (m): tears and cuts do not change it.
inline double meanRestLength(const Cloth& c) { return c.minSplitRest / kMinSplitFraction; }
inline float minTearSplitRest(const Cloth& c) { return c.minSplitRest * float(kMinTearSplitFraction / kMinSplitFraction); }
// No confetti (issue 13 goal 2): a one-point split never sets loose a piece of less rest area than
// this many squared mean rest lengths; the piece stays on as a flap. On a grid of spacing h a rest
// triangle is h^2 / 2 and the mean rest length about 1.14 h, so 2 mean^2 is about 5.2 triangles:
// "a few rest triangles of the mesh" at every resolution, and above the five the tests hold a tear
// to (TearScenes.*Scraps*). At 1.5 mean^2 (3.9 triangles) the split set loose pieces of 4.0 on one
// thread (the pull at 60 deg, 80 a side: bench/README.md, "No confetti: the bound the tests hold").
// A mesh of fewer than 16 x 4 triangles has no confetti (five of its triangles are a thirteenth of
// it or more: Onal's bow tie of two triangles must come apart).
constexpr double kMinLooseAreaFraction = 2.0;
constexpr size_t kMinLooseMeshTriangles = 64;
inline double minLooseArea(const Cloth& c) {
    if (c.triangles.size() < kMinLooseMeshTriangles) return 0.0;
    const double meanRest = meanRestLength(c);
    return kMinLooseAreaFraction * meanRest * meanRest;
}

// Builds the cloth from a mesh: particles at the rest positions, one spring per unique edge, one
// bend-shear spring per interior edge. Refuses non-manifold edges (3+ triangles) and degenerate
// triangles with a message.
Result<Cloth> buildCloth(const MeshData& mesh, float density);

// The cloth as a mesh again, torn or not: every particle a vertex (a torn seam's two sides are two
// vertices), every triangle with its corner UVs. Positions are where the particles are now
// (`restShape` false: an export of what the user sees) or their rest positions (true: a mesh that
// builds the same cloth, unstretched). saveObj writes it; loadObj reads it back with the same pieces.
MeshData clothMesh(const Cloth& cloth, bool restShape = false);

// ---- pure kernels (unit-tested without a world) -------------------------------------------------

// Onal Eq. 1-4: distance between the opposite corners c (of triangle a,b,c) and d (of triangle b,a,d)
// when both triangles lie flat, from the five rest edge lengths.
//   alpha = acos((b^2 + c^2 - a^2) / 2bc), theta = alpha + beta, p = sqrt(b^2 + d^2 - 2bd cos theta)
// Here with the shared edge e=|AB|, and the corner A: |AC| = ac, |BC| = bc, |AD| = ad, |BD| = bd.
double bendRestLength(double e, double ac, double bc, double ad, double bd);

double triangleArea(const Vec3d& a, const Vec3d& b, const Vec3d& c);
double uvArea(const Vec2d& a, const Vec2d& b, const Vec2d& c); // signed

// Spring weight (area / rest^2) from the adjacent rest triangle areas.
float springWeight(double adjacentArea, double restLength);
// Sets the weight of structural spring s from the rest areas of the triangles it lists.
void refreshSpringWeight(Cloth& cloth, Index s);

// Index helpers on the triangle ring.
inline int cornerOf(const Triangle& t, Index particle) {
    for (int i = 0; i < 3; ++i)
        if (t.p[i] == particle) return i;
    return -1;
}
inline int edgeSlotOf(const Triangle& t, Index spring) {
    for (int i = 0; i < 3; ++i)
        if (t.s[i] == spring) return i;
    return -1;
}

// (Re)creates or removes the bend-shear spring across structural spring `s` so that it exists exactly
// when the edge is interior. Rest length from the rest geometry (Eq. 1-4).
void syncBendSpring(Cloth& cloth, Index s);
void removeBendSpring(Cloth& cloth, Index bendIndex);

} // namespace clothtear
