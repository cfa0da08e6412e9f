// The app's input state: what a frame sees of the events applied to it.
#include "input_state.h"

#include <gtest/gtest.h>

using namespace clothtear::app;

TEST(AppInputState, ClickShorterThanAFrameIsStillSeenAsHeld) {
    InputState s;
    s.apply({0, InputKind::Move, 10.f, 20.f, 0});
    s.apply({0, InputKind::Down, 0, 0, 0});
    s.apply({0, InputKind::Up, 0, 0, 0});
    s.apply({0, InputKind::KeyDown, 0, 0, 80});
    s.apply({0, InputKind::KeyUp, 0, 0, 80});
    s.apply({0, InputKind::Scroll, 0.f, 2.f, 0});
    s.apply({0, InputKind::Char, 0, 0, 'x'});
    EXPECT_TRUE(s.buttonHeld(0));
    EXPECT_FALSE(s.buttons[0]);
    EXPECT_TRUE(s.keyHeld(80));
    EXPECT_FLOAT_EQ(s.wheelY, 2.f);
    EXPECT_EQ(s.pending.size(), 7u);
    EXPECT_EQ(s.chars.size(), 1u);
    s.endFrame();
    EXPECT_FALSE(s.buttonHeld(0));
    EXPECT_FALSE(s.keyHeld(80));
    EXPECT_FLOAT_EQ(s.wheelY, 0.f);
    EXPECT_TRUE(s.pending.empty());
    EXPECT_FLOAT_EQ(s.mouseX, 10.f); // the cursor stays where it is
}
