// --save and --load through the `clothtear` binary (docs/world-file.md): a run saved and continued
// ends where one uninterrupted run ends; bad files and bad combinations get one line and status 2
// before any work.
#include "clothtear/world_file.h"
#include "cli_harness.h"

#include <nlohmann/json.hpp>

using namespace clitest;

namespace {

class CliWorldFile : public CliTest {
  protected:
    nlohmann::json report(const std::string& name) { return nlohmann::json::parse(slurp(dir / name)); }
    std::string path(const char* name) { return (dir / name).string(); }
};

const std::string kPull = "--headless --scene pull --set cloth.resolution_x=12 --set cloth.resolution_y=12 ";

} // namespace

// One second, saved; loaded and run one more: the same state as two seconds in one run, torn.
TEST_F(CliWorldFile, SavedAndContinuedRunEndsWhereOneRunEnds) {
    const std::string saved = path("pull.ctw");
    RunResult r = run(kPull + "--seconds 1.5 --save '" + saved + "' --json '" + path("first.json") + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    r = run("--headless --load '" + saved + "' --seconds 1.5 --json '" + path("second.json") + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    r = run(kPull + "--seconds 3 --json '" + path("whole.json") + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json first = report("first.json"), second = report("second.json"), whole = report("whole.json");
    EXPECT_GT(whole["tears_total"].get<int>(), 0) << "the pull tears within 3 s";
    EXPECT_EQ(second["state_hash"], whole["state_hash"]);
    EXPECT_EQ(second["steps"], 180);
    EXPECT_EQ(second["tears_total"], whole["tears_total"]);
    EXPECT_EQ(second["scene"], "load:" + saved);
    EXPECT_EQ(second["loaded"]["file"], saved);
    EXPECT_EQ(second["loaded"]["steps"], 90);
    EXPECT_EQ(second["loaded"]["state_hash"], first["state_hash"]) << "the loaded world is the saved one";
    EXPECT_EQ(second["loaded"]["format_version"], clothtear::kWorldFileVersion);
}

// --set applies on top of the file (here: wind, which changes the continuation), except parameters
// that rebuild the cloth; --scene with --load is refused, not ignored.
TEST_F(CliWorldFile, SetAppliesOnTopSceneAndRebuildsAreRefused) {
    const std::string saved = path("pull.ctw");
    ASSERT_EQ(run(kPull + "--seconds 0.2 --save '" + saved + "'").status, 0);
    const std::string load = "--headless --load '" + saved + "' --seconds 0.2 --json '" + path("r.json") + "'";
    ASSERT_EQ(run(load).status, 0);
    const std::string plain = report("r.json")["state_hash"];
    ASSERT_EQ(run(load + " --set wind.enabled=1").status, 0);
    EXPECT_NE(report("r.json")["state_hash"], plain) << "the wind blew on the loaded cloth";

    std::string args = load + " --set cloth.resolution_x=8";
    expectRefused(run(args), args,
                  {"clothtear: --set cloth.resolution_x=8: cloth.resolution_x rebuilds the cloth, which would replace "
                   "the loaded one; not with --load"});
    args = load + " --scene curtain";
    expectRefused(run(args), args,
                  {"clothtear: --load and --scene: the world file holds the scene and its cloth; give one of them"});
    args = load + " --set tear.threshold=lots";
    expectRefused(run(args), args, {"--set tear.threshold=lots: parameter 'tear.threshold': 'lots' is not a number"});
}

// A bad file: one line naming it and what is wrong, status 2, and no report written (no work done).
TEST_F(CliWorldFile, BadFilesAreRefusedBeforeAnyWork) {
    const std::string saved = path("pull.ctw");
    ASSERT_EQ(run(kPull + "--seconds 0.1 --save '" + saved + "'").status, 0);
    const std::string bytes = slurp(saved);
    const std::string cut = write("cut.ctw", bytes.substr(0, bytes.size() / 2));
    const std::string obj = write("mesh.ctw", "v 0 0 0\n");
    const std::string missing = path("missing.ctw");
    for (const auto& [file, says] : {std::pair{cut, std::string(" (springs): the section says it has")},
                                     std::pair{obj, std::string(": byte 0 (header): not a clothtear world file")},
                                     std::pair{missing, std::string(": cannot open: No such file or directory")}}) {
        const std::string args = "--headless --load '" + file + "' --json '" + path("none.json") + "'";
        const RunResult r = run(args);
        expectRefused(r, args, {says.c_str()});
        EXPECT_EQ(r.err.rfind("clothtear: " + file, 0), 0u) << r.err;
        EXPECT_FALSE(fs::exists(dir / "none.json")) << args;
    }
    const std::string args = kPull + "--seconds 0.1 --save '" + path("no/such/dir/w.ctw") + "'";
    expectRefused(run(args), args, {"clothtear: --save: cannot write '", "no/such/dir/w.ctw'"});
}
