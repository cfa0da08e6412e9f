// Every bad input of docs/bad-input.md that can be tried without a window, through the `clothtear`
// binary: one line naming what was wrong (and the file and line where there is one), exit status 2;
// a run that goes non-finite exits 1 and says where. The app's rows are in tests/app.
#include "cli_harness.h"

#include <nlohmann/json.hpp>

#include <sys/stat.h>

using namespace clitest;

namespace {

const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

class BadInput : public CliTest {
  protected:
    // Loads `file` as the scene and expects the refusal to mention each of `mentions`.
    void refusedObj(const std::string& file, std::initializer_list<const char*> mentions) {
        const std::string args = "--headless --seconds 0.1 --scene 'obj:" + file + "'";
        expectRefused(run(args), args, mentions);
    }
};

TEST_F(BadInput, ObjMissingDirectoryOrNotARegularFile) {
    refusedObj((dir / "missing.obj").string(), {"missing.obj: cannot open"});
    fs::create_directory(dir / "folder.obj");
    refusedObj((dir / "folder.obj").string(), {"folder.obj: cannot read: is a directory"});
    const std::string fifo = (dir / "pipe.obj").string();
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    refusedObj(fifo, {"pipe.obj: cannot read: not a regular file"});
}

TEST_F(BadInput, ObjWithoutReadPermission) {
    const std::string file = write("secret.obj", kTriangle + "f 1 2 3\n");
    ::chmod(file.c_str(), 0);
    fs::permissions(dir, fs::perms::all); // the user below must reach the file to be refused by it
    // Root reads any file: as root, run the binary as the unprivileged user `nobody` instead.
    std::string prefix;
    if (::geteuid() == 0) {
        if (std::system("command -v setpriv >/dev/null 2>&1") != 0)
            GTEST_SKIP() << "root without setpriv";
        prefix = "--reuid=65534 --regid=65534 --clear-groups ";
    }
    const std::string args = "--headless --seconds 0.1 --scene 'obj:" + file + "'";
    const RunResult r = prefix.empty() ? run(args) : runVia("setpriv " + prefix, args);
    if (r.status == 126 || r.status == 127)
        GTEST_SKIP() << "`nobody` cannot run the binary here: " << r.err;
    expectRefused(r, args, {"secret.obj: cannot open: Permission denied"});
}

TEST_F(BadInput, ObjEmptyBinaryOrHuge) {
    refusedObj(write("empty.obj", ""), {"empty.obj: no faces (the file is empty)"});
    refusedObj(write("elf.obj", std::string("\x7f"
                                            "ELF\x02\x01\x01\0\0\0",
                                            10)),
               {"elf.obj:1: binary data (byte 0x7f"});
    // 257 MiB without writing them: a sparse file. Refused before a byte is read.
    const std::string huge = write("huge.obj", kTriangle);
    fs::resize_file(huge, (uintmax_t(257) << 20));
    refusedObj(huge, {"huge.obj: file is 257 MiB", "at most 256 MiB"});
}

TEST_F(BadInput, ObjIndicesCoordinatesAndFaces) {
    refusedObj(write("range.obj", kTriangle + "f 1 2 3\nf 1 2 40\n"),
               {"range.obj:5: face refers to vertex 40 but only 3 vertices are defined"});
    refusedObj(write("nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n"),
               {"nan.obj:3: vertex 3 has a non-finite coordinate 'nan'"});
    refusedObj(write("line.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n"),
               {"line.obj:4: face is degenerate (zero area)"});
    // Area below 1e-12 of the longest squared edge counts as none.
    refusedObj(write("flat.obj", "v 0 0 0\nv 1 0 0\nv 0.5 1e-13 0\nf 1 2 3\n"),
               {"flat.obj:4: face is degenerate"});
}

// A sliver that is not degenerate loads, and the stability guard keeps its light corner finite.
TEST_F(BadInput, SliverThatIsNotDegenerateLoadsAndStaysFinite) {
    const std::string file = write("sliver.obj", "v -1 1 0\nv 1 1 0\nv -1 -1 0\nv 1 -1 0\nv 0 1.000001 0\n"
                                                 "f 1 3 4\nf 1 4 2\nf 1 2 5\n");
    const RunResult r =
        run("--headless --seconds 1 --set check.finite=1 --scene 'obj:" + file + "' --json -");
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["finite"], true) << j["non_finite_where"];
    EXPECT_EQ(j["triangles"], 3);
}

// Three triangles on one edge: refused (not split), naming the file, the two vertices and the face.
TEST_F(BadInput, ObjNonManifoldEdgeIsRefused) {
    refusedObj(write("fin.obj", kTriangle + "v 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n"),
               {"fin.obj: non-manifold edge between vertices 1 and 2", "face 3"});
    refusedObj(write("twice.obj", kTriangle + "f 1 2 3\nf 1 2 3\n"),
               {"twice.obj: faces 1 and 2 use the same three vertices (a doubled face)"});
}

TEST_F(BadInput, ValuesThatAreNotNumbersOrNotFinite) {
    for (const char* value : {"nan", "inf", "-inf", "1e999", "0x10", "1,5", ""}) {
        const std::string args = std::string("--headless --seconds 0.1 --set 'gravity.y=") + value + "'";
        expectRefused(run(args), args, {"gravity.y"});
    }
    const std::string args = "--headless --seconds 0.1 --set cloth.resolution_x=2049";
    expectRefused(run(args), args, {"cloth.resolution_x", "outside the valid range [2, 2048]"});
}

TEST_F(BadInput, CommandLineValuesCli11Checks) {
    for (const char* args : {"--headless --seconds abc", "--headless --seconds -1", "--headless --bogus"})
        expectRefused(run(args), args, {"--help"});
}

// --cut (the knife, knife.h): not numbers, not two numbers a point, one point, not finite, no
// length, a bad time or one after the run's end. One line each, before any work.
TEST_F(BadInput, CutStrokesThatAreNoCut) {
    const struct {
        const char* cut;
        const char* says;
    } cases[] = {
        {"'0.1,0.2'", "--cut '0.1,0.2': a cut needs at least two points (got 1)"},
        {"'a,0;1,1'", "point 1: 'a' is not a number"},
        {"'0,0;1,2,3'", "point 2 '1,2,3' is not two numbers U,V"},
        {"'0,0;;1,1'", "point 2 '' is not two numbers U,V"},
        {"'0,nan;0,1'", "point 1 of the cut is not a finite number"},
        {"'0,0;1e999,0'", "point 2: '1e999' is not a number"},
        {"'0,0;2e5,0'", "point 2 of the cut is beyond +-1e5 m"},
        {"'0.3,0.3;0.3,0.3'", "the cut has no length"},
        {"'x:0,1;0,-1'", "'x' is not a time in seconds"},
        {"'-1:0,1;0,-1'", "'-1' is not a time in seconds"},
        {"'9:0,1;0,-1'", "at 9 s, after the end of the run (--seconds 0.2)"},
    };
    for (const auto& c : cases) {
        const std::string args = std::string("--headless --scene curtain --seconds 0.2 --cut ") + c.cut;
        expectRefused(run(args), args, {c.says});
    }
}

TEST_F(BadInput, ConfigFileErrorsNameFileAndLine) {
    const std::string missing = (dir / "missing.cfg").string();
    expectRefused(run("--headless --config '" + missing + "'"), "missing config",
                  {"missing.cfg: cannot open config file"});
    const std::string bad = write("bad.cfg", "# ok\nscene = tension\ntear.threshold = lots\n");
    expectRefused(run("--headless --config '" + bad + "'"), "bad config",
                  {"bad.cfg:3: parameter 'tear.threshold': 'lots' is not a number"});
    const std::string binary = write("bin.cfg", std::string("\0\1\2", 3));
    expectRefused(run("--headless --config '" + binary + "'"), "binary config", {"bin.cfg:1: binary data"});
}

TEST_F(BadInput, WindowOptionsWithHeadlessAreRefused) {
    const std::string script = write("s.txt", "0 move 1 1\n");
    const std::string args = "--headless --seconds 0.1 --script '" + script + "'";
    expectRefused(run(args), args, {"--script"}); // app build: needs the window; core build: unknown option
    const std::string pipeline = "--headless --seconds 0.1 --no-pipeline"; // the runner has no frame to overlap
    expectRefused(run(pipeline), pipeline, {"--no-pipeline"});
}

TEST_F(BadInput, UnwritableReportPath) {
    const std::string args =
        "--headless --seconds 0.05 --json '" + (dir / "no/such/dir/r.json").string() + "'";
    expectRefused(run(args), args, {"cannot write report to", "r.json"});
}

// Unsafe parameters on purpose: the run exits 1 and the report says where the first NaN/Inf was.
TEST_F(BadInput, RunThatBlowsUpExits1AndSaysWhere) {
    const std::string report = (dir / "r.json").string();
    const RunResult r =
        run("--headless --scene curtain --seconds 0.2 --set time.stability_guard=0 --set limit.enabled=0 "
            "--set material.stretch_stiffness=1e6 --set check.finite=1 --json '" +
            report + "'");
    EXPECT_EQ(r.status, 1) << r.err;
    const nlohmann::json j = nlohmann::json::parse(slurp(report));
    EXPECT_EQ(j["finite"], false);
    const std::string where = j["non_finite_where"];
    EXPECT_NE(where.find("after phase '"), std::string::npos) << where;
    EXPECT_NE(where.find(": particle "), std::string::npos) << where;
}

} // namespace
