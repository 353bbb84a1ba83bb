// `convexloc intersect`, run as a user runs it: answers for lines and planes, clipping,
// standard input, the file format's rules, and every way a LINES file or the usage can be
// wrong (exit 1 with FILE:LINE, or 2 with the usage; nothing on stdout either way).
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "cli_run.hpp"

namespace {

using cli_test::q;
using Outcome = cli_test::Result;

// The intersect tests: a unit square and a cube in the scratch directory, which is where the
// tool runs, so that the tests name their files plainly.
class CliIntersect : public cli_test::Cli {
 protected:
  void SetUp() override {
    Cli::SetUp();
    write("square.txt", "0 0\n1 0\n1 1\n0 1\n");
    write("cube.off",
          "OFF\n8 6 0\n-1 -1 -1\n1 -1 -1\n1 1 -1\n-1 1 -1\n-1 -1 1\n1 -1 1\n1 1 1\n-1 1 1\n"
          "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 1 2 6 5\n4 0 4 7 3\n");
  }
  // writes a scratch file, returns its path
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(scratch(name), std::ios::binary) << text;
    return scratch(name);
  }
  // runs `convexloc intersect ARGS` in the scratch directory, with `input` on stdin
  Outcome run(const std::string& args, const std::string& input = "") const {
    write("stdin", input);
    return Cli::run("intersect " + args, "cd " + q(dir_) + " && cat stdin");
  }
};

TEST_F(CliIntersect, LinesEveryMethod) {
  write("lines.txt",
        "# crossing, missing, along an edge, through one corner\n"
        "-1 0.5 2 0.5\n2 0 2 1\n1 5, 1 6\n\n-1 1 1 -1\n");
  for (const char* m : {"", "--method vertices", "--method bisection", "--method dual"}) {
    const Outcome r = run(std::string("square.txt lines.txt ") + m);
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out, "crosses\nmisses\ntouches\ntouches\n") << m;
  }
}

TEST_F(CliIntersect, ClipInTheSegmentsDirection) {
  const Outcome r = run("square.txt - --clip",
                        "2 0.5 -1 0.5\n0.25 0.25 0.75 0.75\n2 0.5 3 0.5\n-1 1 1 -1\n"
                        "0 0.5 1 0.5000000000000001\n");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out,
            "1 0.5 0 0.5\n0.25 0.25 0.75 0.75\noutside\n0 0 0 0\n0 0.5 1 0.5000000000000001\n");
}

TEST_F(CliIntersect, CrlfCommentsAndStdin) {
  const Outcome a = run("square.txt -", "# c\r\n-1 0.5 2 0.5 # trailing\r\n\r\n2 0 2 1\r\n");
  EXPECT_EQ(a.code, 0) << a.err;
  EXPECT_EQ(a.out, "crosses\nmisses\n");
}

TEST_F(CliIntersect, Planes) {
  write("planes.txt",
        "0 0 0 1 0 0 0 1 0\n0 0 1 1 0 1 0 1 1\n5 5 5 6 5 5 5 6 5\n1 1 1 -1 1 1 1 -1 1\n"
        "3 0 0 0 3 0 0 0 3\n");
  for (const char* m : {"", "--method vertices", "--method dual"}) {
    const Outcome r = run(std::string("cube.off planes.txt ") + m);
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out, "crosses\ntouches\nmisses\ntouches\ntouches\n") << m;
  }
}

TEST_F(CliIntersect, BadRowsNameTheLineAndWriteNothing) {
  struct Bad {
    const char* shape;
    const char* rows;
    const char* message;
  };
  for (const Bad& b : {Bad{"square.txt", "0 0 1 1\n3 3 3 3\n", "<stdin>:2: the two points"},
                       Bad{"square.txt", "0 0 1 1\n\n0 0 1\n", "<stdin>:3:"},
                       Bad{"square.txt", "0 0 1 1 5\n", "<stdin>:1:"},
                       Bad{"square.txt", "0 0 x 1\n", "<stdin>:1:"},
                       Bad{"cube.off", "0 0 0 1 0 0 0 1 0\n0 0 0 1 1 1 2 2 2\n",
                           "<stdin>:2: the three points of the plane lie on one line"},
                       Bad{"cube.off", "0 0 0 1 0 0 0 1\n", "<stdin>:1:"}}) {
    const Outcome r = run(std::string(b.shape) + " -", b.rows);
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_NE(r.err.find(b.message), std::string::npos) << r.err;
  }
  write("bad.txt", "0 0 1 1\n2 2 2 2\n");
  const Outcome r = run("square.txt bad.txt");
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("bad.txt:2: the two points of the line are equal"), std::string::npos)
      << r.err;
}

TEST_F(CliIntersect, BadUsage) {
  for (const char* args : {"square.txt - --method polar", "cube.off - --method bisection",
                           "cube.off - --clip", "square.txt", "- -"}) {
    const Outcome r = run(args, "0 0 1 1\n");
    EXPECT_EQ(r.code, 2) << args << ": " << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_NE(r.err.find("Usage:"), std::string::npos) << r.err;
  }
}

}  // namespace
