// Every seed of fuzz/corpus/<target>/ and every input a fuzzer once failed on (fuzz/regressions/<target>/)
// goes through its harness (fuzz/harness.h) in ordinary builds: a found problem stays fixed.
#include "harness.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace {

std::string readBytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// Runs every file of fuzz/<kind>/<target>/ through the target's harness; returns how many there were.
size_t replay(const clothtear::fuzz::Target& target, const char* kind) {
    const fs::path dir = fs::path(CLOTHTEAR_FUZZ_DIR) / kind / target.name;
    size_t files = 0;
    if (!fs::exists(dir))
        return 0;
    for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
        if (!e.is_regular_file() || e.path().filename() == "README.md")
            continue;
        ++files;
        EXPECT_EQ(target.run(readBytes(e.path())), "") << e.path();
    }
    return files;
}

} // namespace

TEST(FuzzCorpus, EverySeedPassesItsHarness) {
    for (const clothtear::fuzz::Target& t : clothtear::fuzz::targets())
        EXPECT_GE(replay(t, "corpus"), 5u) << "fuzz/corpus/" << t.name << " has too few seeds";
}

TEST(FuzzCorpus, EveryRegressionInputPassesItsHarness) {
    for (const clothtear::fuzz::Target& t : clothtear::fuzz::targets())
        replay(t, "regressions");
}

// The harnesses must be able to fail, or a passing corpus proves nothing.
TEST(FuzzCorpus, HarnessesRejectBrokenMessages) {
    using clothtear::fuzz::checkMessage;
    EXPECT_EQ(checkMessage("fuzz.obj:3: bad", "fuzz.obj"), "");
    EXPECT_NE(checkMessage("", "fuzz.obj"), "");
    EXPECT_NE(checkMessage("other.obj:3: bad", "fuzz.obj"), "");
    EXPECT_NE(checkMessage("fuzz.obj:3: two\nlines", "fuzz.obj"), "");
}
