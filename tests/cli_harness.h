// Runs the `clothtear` binary as a user does, for the CLI tests: a scratch directory per test, the
// exit status, stdout and stderr, and the check that bad input gets one clear line and status 2.
#pragma once
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace clitest {

namespace fs = std::filesystem;

struct RunResult {
    int status = -1;
    std::string out, err;
};

inline std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// A scratch directory of this test process, removed at the end.
class CliTest : public ::testing::Test {
  protected:
    fs::path dir;
    void SetUp() override {
        ASSERT_TRUE(fs::exists(CLOTHTEAR_BINARY)) << "build the clothtear target first: " << CLOTHTEAR_BINARY;
        dir = fs::temp_directory_path() / ("clothtear_cli_" + std::to_string(::getpid()) + "_" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir);
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
    // Writes `bytes` to a file of the scratch directory and returns its path.
    std::string write(const std::string& name, const std::string& bytes) {
        std::ofstream(dir / name, std::ios::binary) << bytes;
        return (dir / name).string();
    }
    // Runs the binary with `args` (already quoted where needed), capturing stdout and stderr.
    RunResult run(const std::string& args) { return runVia("", args); }
    // The same through a wrapper command (`prefix` ends with a space), e.g. setpriv to drop root.
    RunResult runVia(const std::string& prefix, const std::string& args) {
        const fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
        const std::string cmd = prefix + "'" + CLOTHTEAR_BINARY + "' " + args + " >'" + out.string() +
                                "' 2>'" + err.string() + "'";
        const int raw = std::system(cmd.c_str());
        RunResult r;
        r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
        r.out = slurp(out);
        r.err = slurp(err);
        return r;
    }
};

inline void expectRefused(const RunResult& r, const std::string& args,
                          std::initializer_list<const char*> mentions) {
    EXPECT_EQ(r.status, 2) << args << "\nstderr: " << r.err;
    for (const char* m : mentions)
        EXPECT_NE(r.err.find(m), std::string::npos) << args << ": '" << m << "' not in: " << r.err;
    // One message, on stderr, starting with the program name.
    EXPECT_EQ(r.err.rfind("clothtear: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

} // namespace clitest
