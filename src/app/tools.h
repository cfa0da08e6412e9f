// The interaction tools (Keserica ch. 5): drag, wind, impulse, ball, pin; and the knife (Onal 5.2). They act on the World through
// its public state (positions, velocities, pins, drivers, balls); no GL here, so they are unit-testable.
//
// Handles: a tool that holds a particle keeps its index, which stays valid because tearing only
// appends particles (cloth.h); a rebuild of the cloth cancels the hold (App::rebuildWorld).
#pragma once
#include "camera.h"
#include "clothtear/world.h"

#include <vector>

namespace clothtear::app {

enum class Tool : int { Drag = 0, Wind, Impulse, Ball, Pin, Knife, Count };
const char* toolName(Tool tool);

struct ToolSettings {
    float radiusPx = 70.f;     // px, [5, 400]     screen radius of the wind and impulse tools
    float windPressure = 6.f;  // Pa = N/m^2, [0, 2000] wind tool force per unit cloth area at the centre
    float impulse = 3.f;       // m/s, [0, 50]     impulse tool velocity change at the centre
    bool windFixed = false;    //                  wind source fixed in place; it blows until unfixed
    float maxDragSpeed = 40.f; // m/s, [1, 500]    how fast the grabbed particle may chase the cursor
};

// What the tools need to know about the view: camera and window size (window coordinates).
struct View {
    OrbitCamera camera;
    Mat4 viewProjection = Mat4::Identity();
    float width = 1.f, height = 1.f;
    Ray rayAt(const Vec2& cursor) const { return rayThroughPixel(camera, cursor.x(), cursor.y(), width, height); }
};
View makeView(const OrbitCamera& camera, float width, float height);

// ---- drag ------------------------------------------------------------------------------------------
struct DragState {
    Index particle = kNone;            // the grabbed particle
    bool wasPinned = false;            // restored on release
    struct Held {
        Index particle;
        bool wasPinned;
        Vec3 offset; // from the grabbed particle at grab time
    };
    std::vector<Held> patch;           // the other particles within grab.radius, moved rigidly with it
    Vec3 planePoint = Vec3::Zero();    // the camera-facing plane through the grab point
    Vec3 planeNormal = Vec3::UnitZ();
    Vec3 grabOffset = Vec3::Zero();    // particle minus hit point at grab time
    Vec3 target = Vec3::Zero();        // where the particle should be at the end of the next frame
    bool active() const { return particle != kNone; }
};
// Picks the triangle under the cursor and grabs its corner nearest to the hit. False when nothing is hit.
bool beginDrag(World& world, DragState& drag, const View& view, const Vec2& cursor, float grabRadius = 0.f);
void moveDrag(DragState& drag, const View& view, const Vec2& cursor);
// Lets go; keepPinned leaves the particle pinned where it is (the pin key).
void releaseDrag(World& world, DragState& drag, bool keepPinned);
// Around each world.step(): drivers move the held particles to their targets over one frame.
// dragBeforeStep returns how many drivers it appended; dragAfterStep removes them again, and frees the
// copies that tearing made of held particles during the step: a split copies the particle's flags, so
// the copy would otherwise stay pinned in mid-air, held by nobody. (A copy has its original's rest
// position; tearing appends copies at the end, from particlesBefore on.)
size_t dragBeforeStep(World& world, const DragState& drag, float maxSpeed);
void dragAfterStep(World& world, const DragState& drag, size_t pushed, size_t particlesBefore);

// ---- wind and impulse ------------------------------------------------------------------------------
// The source of the wind tool: where on screen it blows and along which direction. Fixing the source
// keeps the view it was set from, so it stays in place while the camera moves.
struct WindSource {
    View view;
    Vec2 center = Vec2::Zero();
    Vec3 direction = Vec3(0, 0, -1); // unit, along the view ray through the centre
};
WindSource windSourceAt(const View& view, const Vec2& cursor);
// Keserica 5.2.2: force = pressure * area share * falloff along the direction, for `seconds`.
// Returns the number of particles affected.
int applyWind(World& world, const WindSource& source, float radiusPx, float pressure, float seconds);
// Keserica 5.2.1: one-shot velocity change along the view ray; negative dv pulls towards the camera.
int applyScreenImpulse(World& world, const View& view, const Vec2& cursor, float radiusPx, float dv);
// Adds dv to a particle's velocity (and wakes a sleeping cloth).
void addVelocity(World& world, Index p, const Vec3& dv);

// ---- ball and pin ------------------------------------------------------------------------------------
// A ball leaving the camera towards the cursor with the radius, speed and mass of settings.scene.
// When the cursor is over the cloth (or the ground) and that point is within reach at this speed, the
// ball is launched on the flat ballistic arc that passes through it; otherwise straight along the ray.
struct Throw {
    Ball ball;
    bool aimed = false;        // on an arc through the point under the cursor
    float neededSpeed = 0.f;   // m/s, the slowest throw that reaches that point (0: nothing under the cursor)
};
Throw throwBall(const World& world, const View& view, const Vec2& cursor);

// Launch velocity of speed `speed` from `from` that reaches `to` under constant acceleration `g`, on the
// faster (flatter) of the two arcs. Solves |d - g t^2 / 2| = s t for t, a quadratic in t^2:
//   (|g|^2 / 4) t^4 - (d.g + s^2) t^2 + |d|^2 = 0,  then v = d / t - g t / 2.
// False when out of reach; minSpeed = sqrt(|g||d| - d.g) is the slowest throw that reaches it.
bool ballisticVelocity(const Vec3& from, const Vec3& to, const Vec3& g, float speed, Vec3& velocity, float& minSpeed);
// Toggles the pin of the particle under the cursor; returns it, or kNone when nothing is hit.
Index togglePinAt(World& world, const View& view, const Vec2& cursor);

// ---- knife -------------------------------------------------------------------------------------------
// While the left button is held, the stroke follows the cloth under the cursor, read back to rest
// space through the hit triangle's barycentric coordinates: it follows the material when the cloth is
// folded or moving. Each frame cuts the stroke since the last one (World::cut, between frames), so a
// long stroke cuts as it goes. A stroke that comes onto the cloth from outside, or leaves it, is
// carried on in rest space to the cloth's edge (a cut from outside to outside cuts through). Holds
// rest coordinates, not particles: a tear, an undo or a cut never leaves it pointing elsewhere.
struct KnifeState {
    bool held = false;               // the left button is down with the knife
    bool onCloth = false;            // the last cursor position was over the cloth
    bool fromOutside = false;        // came onto the cloth from outside: the next cut reaches back to the edge
    Vec2d last = Vec2d::Zero();      // m, the stroke's last point on the cloth in world.restFrame
    Vec2d direction = Vec2d::Zero(); // unit, the stroke's direction there (zero before it moved)
    std::vector<Vec2> trail;         // window positions of the stroke, drawn as a thin line
    size_t springsCut = 0;           // by this stroke
};
// The rest-frame point (knife.h) of the cloth under the cursor; false over no cloth.
bool restPointUnder(const World& world, const View& view, const Vec2& cursor, Vec2d& point);
void knifeBegin(const World& world, KnifeState& knife, const View& view, const Vec2& cursor);
// Once a frame while held: cuts from the last point to the one under the cursor. Springs cut.
size_t knifeMove(World& world, KnifeState& knife, const View& view, const Vec2& cursor);
void knifeEnd(KnifeState& knife);

} // namespace clothtear::app
