// The CLI tests' harness: the real convexloc binary run through /bin/sh in a scratch
// directory of its own, each run's stdout, stderr and exit status captured, and the helpers
// both halves of the tests (test_cli2d.cpp, test_cli3d.cpp) read their files with.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace cli_test {

namespace fs = std::filesystem;

inline const std::string kBin = CONVEXLOC_BIN;
inline const std::string kData = CONVEXLOC_TEST_DATA;
inline const std::string kAssets = CONVEXLOC_ASSETS;

// a path quoted for /bin/sh
inline std::string q(const std::string& path) {
  std::string out = "'";
  for (char c : path) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// a file of tests/data, quoted
inline std::string data(const std::string& name) {
  return q(kData + "/" + name);
}

// the whole content of a file
inline std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// the lines of a text, without their '\n'
inline std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// the lines that are not '#' comments
inline std::vector<std::string> dataLines(const std::string& text) {
  std::vector<std::string> out;
  for (auto& l : linesOf(text))
    if (!l.empty() && l[0] != '#') out.push_back(l);
  return out;
}

// what one run of the tool gave
struct Result {
  int code = -1;
  std::string out;
  std::string err;
};

// a file of tests/data and what stderr must say about it
struct Rejection {
  const char* file;
  const char* message;
};

// Runs the CLI tests in a scratch directory of their own.
class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "convexloc-cli-XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  // a path in the scratch directory
  std::string scratch(const std::string& name) const { return (fs::path(dir_) / name).string(); }

  // runs `convexloc ARGS` (a shell fragment, so '<' and pipes work); `before` is a shell
  // command piped into it
  Result run(const std::string& args, const std::string& before = "") const {
    const std::string out = scratch("stdout"), err = scratch("stderr");
    std::string cmd = (before.empty() ? "" : before + " | ") + q(kBin) + " " + args + " >" +
                      q(out) + " 2>" + q(err);
    int status = std::system(cmd.c_str());
    Result r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
  }

  // runs the tool and writes its stdout to a scratch file; returns that file's path
  std::string runTo(const std::string& args, const std::string& name) const {
    Result r = run(args);
    EXPECT_EQ(r.code, 0) << args << "\n" << r.err;
    std::ofstream(scratch(name), std::ios::binary) << r.out;
    return scratch(name);
  }

  // the run failed on bad input: exit 1, nothing on stdout, `message` on stderr
  static void expectRejected(const Result& r, const std::string& message) {
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_EQ(r.out, "") << "stdout must stay empty on bad input";
    EXPECT_NE(r.err.find(message), std::string::npos) << "stderr was: " << r.err;
  }

  // the run failed on bad usage: exit 2, nothing on stdout, the message and usage on stderr
  static void expectUsage(const Result& r, const std::string& message = "") {
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_NE(r.err.find("Usage:"), std::string::npos) << "stderr was: " << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << "stderr was: " << r.err;
  }

  std::string dir_;
};

}  // namespace cli_test
