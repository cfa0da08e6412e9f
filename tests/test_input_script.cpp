// Input scripts (src/input): parsing, round trip, and errors with file:line.
#include "input_script.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace clothtear::app;

TEST(InputScript, ParsesEveryEvent) {
    const char* text = "# a comment\n"
                       "0 move 640 360.5\n"
                       "\n"
                       "2 down left   # trailing comment\n"
                       "5 up right\n"
                       "5 click middle\n"
                       "6 scroll 0 -1.5\n"
                       "7 key_down W\n"
                       "9 key_up w\n"
                       "10 key F1\n"
                       "11 char 97\n"
                       "12 end\n";
    auto r = parseInputScript(text, "t.txt");
    ASSERT_TRUE(r.ok()) << r.error;
    const auto& e = r.value.events;
    ASSERT_EQ(e.size(), 12u);
    EXPECT_EQ(e[0].kind, InputKind::Move);
    EXPECT_FLOAT_EQ(e[0].y, 360.5f);
    EXPECT_EQ(e[1].kind, InputKind::Down);
    EXPECT_EQ(e[1].code, 0);
    EXPECT_EQ(e[2].code, 1);
    EXPECT_EQ(e[3].kind, InputKind::Down);
    EXPECT_EQ(e[4].kind, InputKind::Up);
    EXPECT_EQ(e[4].code, 2);
    EXPECT_FLOAT_EQ(e[5].y, -1.5f);
    EXPECT_EQ(e[6].code, 87); // GLFW_KEY_W
    EXPECT_EQ(e[7].code, 87);
    EXPECT_EQ(e[8].code, 290); // GLFW_KEY_F1
    EXPECT_EQ(e[9].kind, InputKind::KeyUp);
    EXPECT_EQ(e[10].code, 97);
    EXPECT_EQ(e[11].kind, InputKind::End);
    EXPECT_EQ(r.value.lastFrame(), 12u);
}

TEST(InputScript, RoundTrips) {
    InputScript s;
    s.events = {{0, InputKind::Move, 12.25f, 700.f, 0},   {3, InputKind::Down, 0, 0, 0},
                {3, InputKind::Move, 13.f, 1.f / 3.f, 0}, {4, InputKind::Up, 0, 0, 0},
                {8, InputKind::Scroll, 0.f, 2.f, 0},      {9, InputKind::KeyDown, 0, 0, 340},
                {9, InputKind::KeyUp, 0, 0, 123},         {10, InputKind::Char, 0, 0, 0x263A},
                {11, InputKind::KeyDown, 0, 0, 32},       {20, InputKind::End, 0, 0, 0}};
    const std::string text = formatInputScript(s);
    auto r = parseInputScript(text, "mem");
    ASSERT_TRUE(r.ok()) << r.error << "\n" << text;
    EXPECT_EQ(r.value.events, s.events) << text;
    EXPECT_EQ(formatInputScript(r.value), text);
}

TEST(InputScript, BadLinesNameFileAndLine) {
    struct Case {
        const char* text;
        const char* expected;
    } cases[] = {
        {"0 move 1 2\n1 jump 3\n", "s.txt:2: unknown event 'jump'"},
        {"0 move 1\n", "s.txt:1: 'move' takes <x> <y>"},
        {"# c\n\nx move 1 2\n", "s.txt:3: expected a frame number"},
        {"5 key W\n4 key W\n", "s.txt:2: frame 4 comes after frame 5"},
        {"0 down thumb\n", "s.txt:1: unknown button 'thumb'"},
        {"0 key NOPE\n", "s.txt:1: unknown key 'NOPE'"},
        {"0 move 1 abc\n", "s.txt:1: bad number"},
        {"0 end\n1 key W\n", "s.txt:2: event after 'end'"},
        {"7\n", "s.txt:1: missing event"},
    };
    for (const Case& c : cases) {
        auto r = parseInputScript(c.text, "s.txt");
        ASSERT_FALSE(r.ok()) << c.text;
        EXPECT_EQ(r.error.rfind(c.expected, 0), 0u) << "got: " << r.error;
    }
}

TEST(InputScript, MissingFileIsAnError) {
    auto r = loadInputScript("/nonexistent/script.txt");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error.find("/nonexistent/script.txt"), std::string::npos);
}

TEST(InputScript, KeyNames) {
    for (int code : {32, 48, 57, 65, 90, 256, 257, 265, 290, 301, 340, 347, 123, 500})
        EXPECT_EQ(keyFromName(keyName(code)), code) << keyName(code);
    EXPECT_EQ(keyFromName("f12"), 301);
    EXPECT_EQ(keyFromName("F0"), -1);
    EXPECT_EQ(keyFromName("KEY_x"), -1);
}

// A script cut at any byte (an interrupted copy, a full disk) either still parses, as the events
// before the cut, or is refused with one line naming the file and the line that was cut.
TEST(InputScript, EveryTruncationParsesOrNamesTheCutLine) {
    const std::string text =
        "# drag and throw\n0 move 640 360\n2 down left\n5 move 700.25 380\n9 up left\n"
        "10 key_down LEFT_CONTROL\n11 scroll 0 -1.5\n12 char 9786\n14 click right\n20 end\n";
    const auto whole = parseInputScript(text, "s.txt");
    ASSERT_TRUE(whole.ok()) << whole.error;
    int refused = 0;
    for (size_t cut = 0; cut < text.size(); ++cut) {
        const std::string part = text.substr(0, cut);
        const auto r = parseInputScript(part, "s.txt");
        const size_t lines = size_t(std::count(part.begin(), part.end(), '\n')) + 1;
        if (r.ok()) {
            // What parsed is a prefix of the whole script's events.
            ASSERT_LE(r.value.events.size(), whole.value.events.size()) << "cut at " << cut;
            for (size_t i = 0; i < r.value.events.size(); ++i)
                if (!(r.value.events[i] == whole.value.events[i]) && i + 1 < r.value.events.size())
                    ADD_FAILURE() << "cut at " << cut << ": event " << i << " differs";
            continue;
        }
        ++refused;
        EXPECT_EQ(r.error.rfind("s.txt:" + std::to_string(lines) + ": ", 0), 0u)
            << "cut at " << cut << ": " << r.error;
        EXPECT_EQ(r.error.find('\n'), std::string::npos) << r.error;
    }
    EXPECT_GT(refused, 10) << "cuts inside a word must be refused";
}
