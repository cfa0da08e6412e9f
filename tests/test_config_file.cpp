// Config files (--config): the parameter table as `key = value` lines, errors with file:line.
#include "clothtear/config_file.h"
#include "clothtear/params.h"
#include "clothtear/scenes.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace clothtear;
namespace fs = std::filesystem;

namespace {

fs::path scratchDir() {
    const fs::path d = fs::temp_directory_path() / ("clothtear_config_" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
}

} // namespace

TEST(ConfigFile, SceneParametersCommentsBlankLinesAndCrlf) {
    const char* text = "# tension with a slit\r\n"
                       "scene = tension\r\n"
                       "\n"
                       "  tension.notch=on   # trailing comment\n"
                       "tear.threshold = 0.3\n"
                       "cloth.pin = sides\n"
                       "tear.threshold = 0.28\n"; // a later line wins
    const Result<ConfigFile> r = parseConfig(text, "t.cfg");
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.value.scene, "tension");
    const std::vector<std::string> expected = {"tension.notch=on", "tear.threshold=0.3", "cloth.pin=sides",
                                               "tear.threshold=0.28"};
    EXPECT_EQ(r.value.assignments, expected);
    World w, plain;
    ASSERT_EQ(loadScene(w, r.value.scene, r.value.assignments), "");
    ASSERT_EQ(loadScene(plain, "tension"), "");
    EXPECT_TRUE(w.settings.scene.tensionNotch);
    EXPECT_FLOAT_EQ(w.settings.tear.threshold, 0.28f);
    EXPECT_EQ(w.settings.cloth.pin, PinMode::LeftRightEdges);
    EXPECT_EQ(w.cloth.triangles.size(), plain.cloth.triangles.size() + 2) << "the notch was cut";
}

TEST(ConfigFile, EmptyFileSetsNothing) {
    const Result<ConfigFile> r = parseConfig("# nothing\n\n", "e.cfg");
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.value.scene, "");
    EXPECT_TRUE(r.value.assignments.empty());
}

TEST(ConfigFile, EveryBadLineNamesFileAndLine) {
    struct Case {
        const char* text;
        const char* expected; // the message starts with this
        const char* mentions; // and contains this
    } cases[] = {
        {"tear.threshold 0.3\n", "c.cfg:1: expected 'key = value'", "tear.threshold 0.3"},
        {"# ok\nnope = 1\n", "c.cfg:2: unknown parameter 'nope'", "--list-params"},
        {"material.density = -1\n", "c.cfg:1: parameter 'material.density'", "outside the valid range"},
        {"material.density = abc\n", "c.cfg:1: parameter 'material.density'", "not a number"},
        {"material.density = nan\n", "c.cfg:1: parameter 'material.density'", "not a number"},
        {"material.density =\n", "c.cfg:1: parameter 'material.density'", "empty value"},
        {"cloth.resolution_x = 1.5\n", "c.cfg:1: parameter 'cloth.resolution_x'", "not an integer"},
        {"cloth.pin = everywhere\n", "c.cfg:1: parameter 'cloth.pin'", "not one of"},
        {"= 3\n", "c.cfg:1: missing parameter name", "'='"},
        {"\n\nscene = nope\n", "c.cfg:3: unknown scene 'nope'", "--list-scenes"},
        {"scene = obj:\n", "c.cfg:1: unknown scene 'obj:'", "--list-scenes"},
        {"scene =\n", "c.cfg:1: scene: empty value", "scene"},
        {"tear.threshold = 0.3\n\x01\x02\x03", "c.cfg:2: binary data (byte 0x01 at column 1)", "not a text"},
    };
    for (const Case& c : cases) {
        const Result<ConfigFile> r = parseConfig(c.text, "c.cfg");
        ASSERT_FALSE(r.ok()) << c.text;
        EXPECT_EQ(r.error.rfind(c.expected, 0), 0u) << "got: " << r.error;
        EXPECT_NE(r.error.find(c.mentions), std::string::npos) << "got: " << r.error;
        EXPECT_EQ(r.error.find('\n'), std::string::npos) << "one line: " << r.error;
    }
}

TEST(ConfigFile, MissingDirectoryAndOversizedFilesAreRefused) {
    const fs::path dir = scratchDir();
    Result<ConfigFile> r = loadConfig((dir / "missing.cfg").string());
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error.find("missing.cfg: cannot open config file"), std::string::npos) << r.error;
    r = loadConfig(dir.string());
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error.find("not a regular file"), std::string::npos) << r.error;
    const fs::path big = dir / "big.cfg";
    { std::ofstream(big) << "# big\n"; }
    fs::resize_file(big, (1u << 20) + 1); // sparse: costs no disk
    r = loadConfig(big.string());
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error.find("at most 1 MiB"), std::string::npos) << r.error;
    const fs::path good = dir / "good.cfg";
    std::ofstream(good) << "scene = flag\nwind.speed = 3\n";
    r = loadConfig(good.string());
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.value.scene, "flag");
    fs::remove_all(dir);
}
