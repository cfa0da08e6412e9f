// Sound events from the tear log (sound_events.h).
#include "sound_events.h"

#include "clothtear/mesh.h"

#include <algorithm>
#include <cmath>

namespace clothtear::audio {
namespace {

// A ball touches the cloth when a particle is within its radius plus the cloth's thickness and a
// centimetre (the contact phase keeps particles at radius + thickness; the margin covers a frame's
// separation on a rebound).
bool ballTouchesCloth(const World& w) {
    const float margin = w.settings.collision.thickness + 0.01f;
    for (const Ball& b : w.balls) {
        const float reach = b.radius + margin;
        for (const Vec3& x : w.cloth.x)
            if ((x - b.x).squaredNorm() <= reach * reach) return true;
    }
    return false;
}

} // namespace

float releasedEnergy(float stiffness, const TearEvent& e) {
    const double k = double(stiffness) * e.weight;
    const double stretch = double(e.strain) * e.restLength;
    return float(0.5 * k * stretch * stretch);
}

TearListener::TearListener(const World& world) : seen_(world.tearLog.events.size()) {
    const MeshFrame frame = meshFrame(world.cloth.rest);
    centre_ = frame.centre;
    right_ = frame.right;
    halfWidth_ = std::max(0.5 * (frame.maxU - frame.minU), 1e-6);
    centre_ += right_ * (0.5 * (frame.maxU + frame.minU)); // the middle of the extent, not the mean
}

void TearListener::collect(const World& world, std::vector<SoundEvent>& out) {
    const std::vector<TearEvent>& log = world.tearLog.events;
    seen_ = std::min(seen_, log.size()); // a restored checkpoint may hold fewer events
    if (!world.balls.empty() && ballTouchesCloth(world)) lastContact_ = world.time;
    const float stiffness = world.settings.material.stretchStiffness;
    for (; seen_ < log.size(); ++seen_) {
        const TearEvent& e = log[seen_];
        SoundEvent s;
        s.time = e.time;
        s.mode = e.mode;
        s.energy = releasedEnergy(stiffness, e);
        const double area = double(e.weight) * e.restLength * e.restLength;
        s.energyDensity = area > 0 ? float(s.energy / area) : 0.f;
        s.length = e.restLength;
        s.pan = float(std::clamp((e.restPos - centre_).dot(right_) / halfWidth_, -1.0, 1.0));
        s.impact = std::abs(e.time - lastContact_) <= kImpactWindow;
        out.push_back(s);
    }
}

} // namespace clothtear::audio
