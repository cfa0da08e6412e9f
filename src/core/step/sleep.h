// Sleep: a cloth at rest is not simulated until something can move it (sleep.cpp).
#pragma once
#include "step_state.h"

namespace clothtear {

// Before a frame: asleep and nothing can touch the cloth this frame? (Wakes it otherwise.)
bool stayAsleep(World& world, StepState& state);
// After a frame: at rest long enough to fall asleep?
void updateSleep(World& world, StepState& state);

// A ball can reach the box [lo, hi] within the frame (where it can be by the frame's end, gravity
// included, grown by its radius and the collision thickness). Sleeping balls cannot.
bool aBallCanReach(const World& world, const Vec3& lo, const Vec3& hi);

// Any parameter differs (compared by value through the parameter table).
bool paramsChanged(const Settings& now, const Settings& then);

// Torn pieces (piece_sleep.cpp). Before a frame the World simulates: wakes the sleeping pieces if
// something can move them. After it: puts the pieces that settled to sleep.
void wakePiecesIfTouched(World& world, StepState& state);
void updatePieceSleep(World& world, StepState& state);
// Wakes every sleeping piece (World::wake).
void wakePieces(World& world, StepState& state);

// Balls (ball_sleep.cpp). Before a frame the World simulates: wakes the sleeping balls that
// something can move, and records where every ball starts the frame. After it: puts the balls to
// sleep that stayed still long enough with no moving cloth within reach.
void wakeBallsIfTouched(World& world, StepState& state);
void updateBallSleep(World& world, StepState& state);
// A frame in which the World sleeps: its awake balls, none of which can reach the cloth (or the
// World would have woken), fly and bounce on the ground as in a frame of the step, and may sleep.
void moveBallsBesideASleepingCloth(World& world, StepState& state);
// Is any ball awake (the ball phases have work)?
bool anyBallAwake(const std::vector<Ball>& balls);
// Frames a ball or a piece must stay still before it sleeps (sleep.delay in frames, at least 1).
int stillFramesToSleep(const Settings& settings);

} // namespace clothtear
