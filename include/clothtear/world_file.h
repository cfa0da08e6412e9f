// World files: the whole state of a World in one versioned binary file, so a torn cloth can be saved
// and later continue exactly where it was (docs/world-file.md has the layout).
//
// What is saved is everything that decides the next frames: the settings (every parameter of the
// table, by name), the cloth (topology, rest data, positions, velocities), balls, drivers, time, step
// count, tear counts, sleep, and the integrator state that outlives a sub-step (Verlet's half kicks,
// implicit Euler's warm start). A loaded World continues bit for bit as the one that saved it: the
// same stateHash right after the load and after any number of further frames.
// Not saved: timings (StepProfile), the list of tear events (their counts are), caches (rebuilt).
#pragma once
#include "clothtear/types.h"
#include "clothtear/world.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace clothtear {

// The version this build writes; it reads this one and kOldestWorldFileVersion. A change of the
// layout is a new version; a parameter added to the table is not (a file without it gets the default).
// Version 2: knife cuts (a fourth tear count, TearMode::Knife, and the number of knife strokes).
// Version 3: the kes hinges' memory (Cloth::bendMemory) after the bend springs; a version 2 file
//            reads as one without (a linear cloth, or kes hinges at rest).
// Version 4: the frames each particle has been still (torn pieces' sleep) at the end of the step
//            state; an older file's particles start counting at the load.
// Version 5: the balls' sleep (Ball::stillFrames, Ball::asleep) at the end of the step state; an
//            older file's balls are awake and start counting at the load.
inline constexpr uint32_t kWorldFileVersion = 5;
inline constexpr uint32_t kOldestWorldFileVersion = 2;

// Largest world file loadWorld reads (refused before reading).
inline constexpr uintmax_t kMaxWorldFileBytes = uintmax_t(1) << 30;

// The file's bytes. Returns "" or why the world cannot be saved (a non-finite state).
std::string serializeWorld(const World& world, std::string& bytes);

// Writes the world to `path`, after reading the bytes back: a world the reader would refuse (a
// parameter a scene or test set outside its valid range, a cloth flown beyond +-1e5 m) is not
// written, so a saved file always loads. Returns "" or one line naming the file.
std::string saveWorld(const World& world, const std::string& path);

// Reads a world file. On error: one line starting with the path, saying what is wrong and where
// (byte offset and section, or the cloth's first invariant violation).
Result<World> loadWorld(const std::string& path);

// The same from bytes in memory (the fuzzer); `source` stands for the file name in messages.
Result<World> parseWorld(std::string_view bytes, const std::string& source);

} // namespace clothtear
