// A fingerprint of the whole simulation state, for determinism tests and the runner's report: the
// same scene, parameters and input give the same hash, bit for bit, on every run.
#pragma once
#include "clothtear/world.h"

#include <cstdint>
#include <string>

namespace clothtear {

// 64-bit FNV-1a over the raw bytes of the live state (positions, velocities, Verlet's half kicks),
// the topology (particles' flags, masses and rest positions, springs, bend-shear springs, triangles
// with their UVs and rest areas, the topology revision), balls, drivers, time and step count.
// Field by field, so struct padding never enters it.
uint64_t stateHash(const World& world);

// "0x" and 16 lower-case hex digits.
std::string hashHex(uint64_t hash);

} // namespace clothtear
