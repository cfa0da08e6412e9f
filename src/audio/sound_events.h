// Sound events: what the synthesizer (rip_synth.h) hears of each tear a World logs.
//
// The energy a tear releases is the strain energy of the spring that tore (cloth.h Spring):
//   E = 1/2 k (strain * L)^2,  k = material.stretch_stiffness * weight   (J)
// A finer mesh halves L and keeps weight (area / L^2), so one spring releases a quarter of the energy
// and a rip of the same length releases half in all. What does not depend on the mesh is the energy
// per area of the spring's cloth, E / (weight L^2) = 1/2 stiffness strain^2 (J/m^2), and the length
// of cloth torn: the synthesizer's loudness follows the first, its grain count the second.
#pragma once
#include "clothtear/tear_events.h"
#include "clothtear/world.h"

#include <cstddef>
#include <vector>

namespace clothtear::audio {

struct SoundEvent {
    double time = 0;                 // s, simulated
    TearMode mode = TearMode::Basic;
    float energy = 0;                // J, released by the spring that tore (above)
    float energyDensity = 0;         // J/m^2, energy / (weight L^2): the same at every resolution
    float length = 0;                // m, cloth torn: the rest length of the spring that tore
    float pan = 0;                   // -1 left .. +1 right: the tear's place across the cloth at rest
    bool impact = false;             // a ball touched the cloth within kImpactWindow of the tear
};

// A tear this long after a ball last touched the cloth still belongs to the hit (s).
inline constexpr double kImpactWindow = 0.1;

// E = 1/2 k (strain L)^2 with k = stiffness * weight (J); 0 for an event without its spring.
float releasedEnergy(float stiffness, const TearEvent& e);

// Turns the tears a World logs into sound events, one frame at a time.
class TearListener {
public:
    // Takes the cloth's extent at rest (for panning); tears already logged are not heard.
    explicit TearListener(const World& world);
    // Appends the events of the tears logged since the last call. Call after each World::step.
    void collect(const World& world, std::vector<SoundEvent>& out);

private:
    size_t seen_ = 0;            // tearLog.events heard so far
    Vec3d centre_, right_;       // the cloth's rest frame (mesh.h MeshFrame)
    double halfWidth_ = 1;       // m, half the rest extent along right_
    double lastContact_ = -1e30; // s, the last frame end at which a ball touched the cloth
};

} // namespace clothtear::audio
