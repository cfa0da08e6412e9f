// What tearing reports: one event per tear, kept in a log for the renderer, stats and reports.
#pragma once
#include "clothtear/types.h"

#include <array>
#include <string>
#include <vector>

namespace clothtear {

// The first three are the physics' tears (Onal 3.2.1-3.2.3); Knife is a spring the knife cut
// (knife.h): one event per edge it opened, so counts, stats and sounds can tell a cut from a tear.
enum class TearMode : int { Basic = 0, WeakPoint = 1, OnePoint = 2, Knife = 3, Count };
const char* tearModeName(TearMode m);

struct TearEvent {
    TearMode mode;
    double time;      // s, simulated
    Vec3d restPos;    // where, in rest space (m)
    Vec2d uv;         // where, in texture space
    float strain;     // strain of the spring that tore
    // The spring that tore, as it was: what a listener needs to estimate the strain energy released,
    // E = 1/2 k (strain * restLength)^2 with k = material.stretch_stiffness * weight (src/audio).
    float restLength = 0; // m
    float weight = 0;     // its stiffness weight (area / length^2, dimensionless; cloth.h Spring)
};

struct TearLog {
    std::vector<TearEvent> events;
    std::array<uint64_t, int(TearMode::Count)> counts{};
    size_t maxEvents = 100000; // older events are kept; beyond this only counts grow
    uint64_t knifeCuts = 0;      // strokes (World::cut calls) that opened at least one spring
    std::string validationError; // first invariant violation found after a tear or cut (when validating)
    void add(const TearEvent& e) {
        counts[int(e.mode)]++;
        if (events.size() < maxEvents) events.push_back(e);
    }
    // Every event, the knife's cut springs included (each changed the topology: undo groups count
    // them); counts[] tells the physics' tears from the knife's.
    uint64_t total() const { return counts[0] + counts[1] + counts[2] + counts[3]; }
};

} // namespace clothtear
