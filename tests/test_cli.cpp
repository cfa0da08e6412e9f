// The `clothtear` binary as a user runs it: bad input exits with status 2 and one clear message,
// and a headless run writes the JSON report with the documented fields.
#include "cli_harness.h"
#include "clothtear/scenes.h"
#include "clothtear/world.h"

#include <nlohmann/json.hpp>

using namespace clitest;

namespace {

// --cut: the knife cuts the default curtain (2 m x 2 m) from top to bottom at u = 0.3 m after 0.2 s:
// two pieces of 1.3 and 0.7 of its 4 m^2 (within two triangles), every knife event at 0.2 s on the
// line, counted in the report.
TEST_F(CliTest, CutSplitsTheCurtainInTwoAtItsTime) {
    const RunResult r = run("--headless --scene curtain --seconds 0.5 --cut '0.2:0.3,1.5;0.3,-1.5' --json -");
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["knife"]["cuts"], 1);
    EXPECT_GE(j["knife"]["springs"].get<int>(), 39) << "an edge a row at least";
    EXPECT_EQ(j["tears"]["knife"], j["knife"]["springs"]);
    ASSERT_EQ(j["pieces"]["count"], 2) << j["pieces"].dump();
    const double triangle = 4.0 / (39 * 39 * 2);
    EXPECT_NEAR(j["pieces"]["areas"][0].get<double>(), 2.6, 2 * triangle);
    EXPECT_NEAR(j["pieces"]["areas"][1].get<double>(), 1.4, 2 * triangle);
    for (const auto& e : j["tear_events"]) {
        if (e["mode"] != "knife") continue;
        EXPECT_NEAR(e["time"].get<double>(), 0.2, 1.0 / 60) << e.dump();
        EXPECT_NEAR(e["rest"][0].get<double>(), 0.3, 0.01) << e.dump();
    }
}

TEST_F(CliTest, UnknownParameterIsRefused) {
    const std::string args = "--headless --seconds 0.1 --set nope=1";
    expectRefused(run(args), args, {"nope", "unknown parameter"});
}

TEST_F(CliTest, OutOfRangeValueIsRefused) {
    const std::string args = "--headless --seconds 0.1 --set material.density=-1";
    expectRefused(run(args), args, {"material.density", "outside the valid range"});
}

TEST_F(CliTest, NonNumericValueIsRefused) {
    const std::string args = "--headless --seconds 0.1 --set material.density=abc";
    expectRefused(run(args), args, {"material.density", "not a number"});
}

TEST_F(CliTest, MalformedAssignmentIsRefused) {
    const std::string args = "--headless --seconds 0.1 --set material.density";
    expectRefused(run(args), args, {"material.density", "key=value"});
}

TEST_F(CliTest, UnknownSceneIsRefused) {
    const std::string args = "--headless --seconds 0.1 --scene nope";
    expectRefused(run(args), args, {"unknown scene 'nope'", "curtain"});
}

TEST_F(CliTest, HeadlessRunWritesTheJsonReport) {
    const fs::path report = dir / "report.json";
    const RunResult r = run("--headless --scene curtain --seconds 0.5 --json '" + report.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    ASSERT_TRUE(fs::exists(report));
    const nlohmann::json j = nlohmann::json::parse(slurp(report));
    for (const char* field :
         {"scene", "seconds", "steps", "substeps", "dt", "particles", "springs", "bend_springs", "triangles",
          "total_mass", "rest_area", "max_strain", "finite", "ms_per_step", "phases"})
        EXPECT_TRUE(j.contains(field)) << "report lacks '" << field << "'";

    // The curtain defaults: 40 x 40 particles on 2 m x 2 m, 0.2 kg/m^2, at least 10 sub-steps at 60 Hz.
    const int n = 40;
    const long triangles = 2L * (n - 1) * (n - 1);
    const long springs = long(n) * n + triangles - 1; // Euler for a disc: V - E + F = 1
    const long border = 4L * (n - 1);
    EXPECT_EQ(j["scene"], "curtain");
    EXPECT_NEAR(j["seconds"].get<double>(), 0.5, 1e-4);
    EXPECT_EQ(j["steps"], 30);
    EXPECT_EQ(j["substeps"], 10);
    // dt: the sub-step the guard took (the frame over frame_substeps), at most 1/600 s.
    EXPECT_NEAR(j["dt"].get<double>(), (1.0 / 60.0) / j["frame_substeps"].get<double>(), 1e-9);
    EXPECT_LE(j["dt"].get<double>(), 1.0 / 600.0 + 1e-12);
    EXPECT_EQ(j["particles"], n * n);
    EXPECT_EQ(j["triangles"], triangles);
    EXPECT_EQ(j["springs"], springs);
    EXPECT_EQ(j["bend_springs"], springs - border);
    EXPECT_NEAR(j["total_mass"].get<double>(), 0.2 * 4.0, 1e-6);
    EXPECT_NEAR(j["rest_area"].get<double>(), 4.0, 1e-9);
    // max_strain: the largest (length - rest) / rest over the structural springs at the end. The
    // same run in this process, measured from the positions, gives the value itself. Physically:
    // the top row carries the weight below it, rho g H = 3.9 N per metre of width, on springs of
    // S = 60 N/m per metre (vertical ones, weight 1) plus S / 4 along the vertical (the diagonals),
    // a static strain of 3.9 / 75 = 0.052 (the settled curtain's top row: 0.057). Falling from rest
    // at strain 0 the curtain swings about that; where it first hits the 10% limit (0.15 s in) the
    // limit's inelastic correction takes most of the swing out, so at 0.5 s it is at least half of it
    // (measured: 0.067, never below 0.058 from 0.4 s on). The limit holds it near 10% from above.
    const double maxStrain = j["max_strain"].get<double>();
    clothtear::World same;
    ASSERT_EQ(clothtear::loadScene(same, "curtain"), "");
    for (int f = 0; f < 30; ++f)
        same.step();
    double measured = 0;
    for (const clothtear::Spring& s : same.cloth.springs)
        measured = std::max(measured, double((same.cloth.x[s.b] - same.cloth.x[s.a]).norm()) / s.rest - 1.0);
    EXPECT_NEAR(maxStrain, measured, 1e-6);
    EXPECT_GT(maxStrain, 0.5 * 0.2 * 9.81 * 2.0 / (1.25 * 60.0));
    EXPECT_LT(maxStrain, 0.2);
    EXPECT_EQ(j["finite"], true);
    EXPECT_GE(j["ms_per_step"].get<double>(), 0.0);

    const nlohmann::json& phases = j["phases"];
    ASSERT_TRUE(phases.is_object());
    for (int p = 0; p < int(clothtear::Phase::Count); ++p) {
        const char* name = clothtear::phaseName(clothtear::Phase(p));
        ASSERT_TRUE(phases.contains(name)) << name;
        EXPECT_TRUE(phases[name].contains("runs")) << name;
        EXPECT_TRUE(phases[name].contains("ms_per_step")) << name;
    }
    // Every sub-step of the 30 frames: the guard's sub-steps for the material's stable step.
    const int substeps = 30 * j["frame_substeps"].get<int>();
    EXPECT_GE(substeps, 300);
    EXPECT_EQ(j["guard_capped_springs"], 0); // the default curtain keeps the material as set
    EXPECT_EQ(j["guard_stiffness_kept"], 1.0);
    EXPECT_EQ(phases["integrate"]["runs"], substeps);
    EXPECT_EQ(phases["collide"]["runs"], 0);        // no balls
    EXPECT_EQ(phases["contact"]["runs"], substeps); // the ground is on
    EXPECT_EQ(phases["wind"]["runs"], 0);      // no wind in the curtain scene
}

TEST_F(CliTest, JsonToStdout) {
    const RunResult r = run("--headless --scene corners --seconds 0.1 --json -");
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["scene"], "corners");
    EXPECT_EQ(j["steps"], 6);
}

// --mesh puts any scene on an OBJ (the same as --scene SCENE:obj:FILE); a missing file is named;
// a cloth pinned whole is warned about on stderr and in the report.
TEST_F(CliTest, MeshOptionComposesAnObjWithTheSceneAndWarnings) {
    clothtear::MeshData m = clothtear::makeGridMesh(9, 7, 1.0, 0.8);
    for (clothtear::Vec3d& p : m.positions) p = clothtear::Vec3d(p.x(), 0.0, -p.y()); // flat, as a modeller exports a plane
    const fs::path obj = dir / "flat.obj";
    ASSERT_TRUE(clothtear::saveObj(m, obj.string()));
    RunResult r = run("--headless --scene pull --mesh '" + obj.string() + "' --seconds 0.1 --json -");
    ASSERT_EQ(r.status, 0) << r.err;
    nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["scene"], "pull:obj:" + obj.string());
    EXPECT_EQ(j["particles"], 63);
    EXPECT_TRUE(j["warnings"].empty()) << j["warnings"];
    // The top (far) row and the hand, as on the same grid built in; not every particle.
    const RunResult grid = run("--headless --scene pull --set cloth.resolution_x=9 --set cloth.resolution_y=7 "
                               "--set cloth.width=1 --set cloth.height=0.8 --seconds 0.1 --json -");
    ASSERT_EQ(grid.status, 0) << grid.err;
    const int pinned = nlohmann::json::parse(grid.out)["pinned"];
    EXPECT_GT(pinned, 9);
    EXPECT_EQ(j["pinned"], pinned);

    const std::string missing = "--headless --scene pull --mesh '" + (dir / "none.obj").string() + "' --seconds 0.1";
    expectRefused(run(missing), missing, {"none.obj"});

    r = run("--headless --seconds 0.05 --set cloth.resolution_x=2 --set cloth.pin=sides --json -");
    ASSERT_EQ(r.status, 0) << r.err;
    j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j["warnings"].size(), 1u);
    EXPECT_NE(j["warnings"][0].get<std::string>().find("every particle is pinned"), std::string::npos);
    EXPECT_NE(r.err.find("warning: every particle is pinned"), std::string::npos) << r.err;
}

// --export-obj writes the cloth as it ends (torn) with its UVs; an unwritable path is named, status 2.
TEST_F(CliTest, ExportObjWritesTheTornCloth) {
    const fs::path obj = dir / "torn.obj";
    RunResult r = run("--headless --scene ball-r0.5-v3 --set cloth.resolution_x=20 --set cloth.resolution_y=20 "
                      "--seconds 1.5 --export-obj '" + obj.string() + "' --json -");
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    ASSERT_GT(j["tears_total"].get<int>(), 0);
    clothtear::Result<clothtear::MeshData> mesh = clothtear::loadObj(obj.string());
    ASSERT_TRUE(mesh.ok()) << mesh.error;
    EXPECT_EQ(mesh.value.triangles.size(), j["triangles"].get<size_t>());
    EXPECT_EQ(mesh.value.positions.size(), j["particles"].get<size_t>());
    const std::string bad = "--headless --seconds 0.05 --export-obj '" + (dir / "no/such/dir/x.obj").string() + "'";
    expectRefused(run(bad), bad, {"--export-obj: cannot write", "x.obj"});
}

// --config: the file's scene and parameters, with --scene and --set on the command line winning.
TEST_F(CliTest, ConfigFileSetsSceneAndParametersAndTheCommandLineWins) {
    const std::string cfg = write("run.cfg", "# corners, coarse\nscene = corners\ncloth.resolution_x = 10\n"
                                             "cloth.resolution_y = 12 # rows\n");
    RunResult r = run("--headless --seconds 0.05 --config '" + cfg + "' --json -");
    ASSERT_EQ(r.status, 0) << r.err;
    nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["scene"], "corners");
    EXPECT_EQ(j["particles"], 120);
    EXPECT_EQ(j["pinned"], 2);
    r = run("--headless --seconds 0.05 --config '" + cfg + "' --scene curtain --set cloth.resolution_y=5 --json -");
    ASSERT_EQ(r.status, 0) << r.err;
    j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["scene"], "curtain");
    EXPECT_EQ(j["particles"], 50);
    EXPECT_EQ(j["pinned"], 10);
}

// The report's state_hash: the same run twice gives the same hash; a different run another one.
TEST_F(CliTest, ReportHasTheStateHashAndItRepeats) {
    const std::string args = "--headless --scene tension --set tension.notch=1 --seconds 0.5 --json -";
    const RunResult a = run(args), b = run(args), c = run(args + " --set tension.speed=0.6");
    ASSERT_EQ(a.status, 0) << a.err;
    ASSERT_EQ(b.status, 0) << b.err;
    ASSERT_EQ(c.status, 0) << c.err;
    const std::string ha = nlohmann::json::parse(a.out)["state_hash"], hb = nlohmann::json::parse(b.out)["state_hash"];
    const std::string hc = nlohmann::json::parse(c.out)["state_hash"];
    EXPECT_EQ(ha.size(), 18u) << ha; // 0x and 16 hex digits
    EXPECT_EQ(ha.rfind("0x", 0), 0u) << ha;
    EXPECT_EQ(ha, hb);
    EXPECT_NE(ha, hc);
}

} // namespace
