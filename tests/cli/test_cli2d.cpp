// The convexloc tool on polygons, as a user runs it: classify, info and generate on the 2D
// files in tests/data, bad input and bad usage, and the shipped 2D examples.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "cli_run.hpp"

namespace {

using namespace cli_test;

const char* const kMethods[] = {"halfplane", "wedge", "slab", "uniform", "polar"};
const char* const kKinds[] = {"regular",    "random", "ellipse",    "sliver",
                              "tiny-edges", "offset", "degenerate", "triangle"};

// === classify: answers

TEST_F(Cli, ClassifyKnownAnswersEveryMethod) {
  const std::string expected = slurp(kData + "/hexagon_expected.txt");
  for (const char* m : kMethods) {
    Result r = run("classify " + data("hexagon.txt") + " " + data("hexagon_points.txt") +
                   " --method " + m);
    EXPECT_EQ(r.code, 0) << m << ": " << r.err;
    EXPECT_EQ(r.out, expected) << "method " << m;
    EXPECT_EQ(r.err, "");
  }
}

TEST_F(Cli, ClassifyExpectedFileCoversEveryAnswer) {
  // the reference answers themselves: vertices and exact edge points are boundary,
  // one ulp off them goes either way, the centre is inside, far points are outside
  auto lines = linesOf(slurp(kData + "/hexagon_expected.txt"));
  ASSERT_EQ(lines.size(), 32u);
  EXPECT_EQ(lines[0], "inside");    // centre
  EXPECT_EQ(lines[3], "boundary");  // vertex (2, 0)
  EXPECT_EQ(lines[9], "boundary");  // edge midpoint (1.5, 1)
  EXPECT_EQ(lines[16], "outside");  // one ulp right of vertex (2, 0)
  EXPECT_EQ(lines[17], "inside");   // one ulp left of vertex (2, 0)
  EXPECT_EQ(lines[22], "outside");  // on an edge's line, past its end
  EXPECT_EQ(lines[26], "outside");  // far away
}

TEST_F(Cli, ClassifyDefaultMethodIsPolar) {
  Result a = run("classify " + data("hexagon.txt") + " " + data("hexagon_points.txt"));
  Result b =
      run("classify " + data("hexagon.txt") + " " + data("hexagon_points.txt") + " -m polar");
  EXPECT_EQ(a.code, 0);
  EXPECT_EQ(a.out, b.out);
  EXPECT_EQ(a.out, slurp(kData + "/hexagon_expected.txt"));
}

TEST_F(Cli, ClassifyResolutionDoesNotChangeAnswers) {
  const std::string expected = slurp(kData + "/hexagon_expected.txt");
  for (const char* m : {"uniform", "polar"})
    for (const char* res : {"1", "2", "7", "1000"}) {
      Result r = run("classify " + data("hexagon.txt") + " " + data("hexagon_points.txt") + " -m " +
                     m + " --resolution " + res);
      EXPECT_EQ(r.code, 0) << r.err;
      EXPECT_EQ(r.out, expected) << m << " at resolution " << res;
    }
}

TEST_F(Cli, ClassifyPolygonClockwiseCrlfWithRepeatsGivesSameAnswers) {
  const std::string expected = slurp(kData + "/hexagon_expected.txt");
  for (const char* m : kMethods) {
    Result r = run("classify " + data("hexagon_clockwise_crlf.txt") + " " +
                   data("hexagon_points.txt") + " -m " + m);
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out, expected) << m;
  }
}

TEST_F(Cli, ClassifyReadsEveryTextFormat) {
  const std::string expected = slurp(kData + "/format_expected.txt");
  for (const char* f : {"format_crlf.txt", "format_commas.txt", "format_comments_blank.txt",
                        "format_no_final_newline.txt", "format_signs_exponents.txt",
                        "format_crlf_no_final_newline.txt"}) {
    Result r = run("classify " + data("hexagon.txt") + " " + data(f));
    EXPECT_EQ(r.code, 0) << f << ": " << r.err;
    EXPECT_EQ(r.out, expected) << f;
  }
}

TEST_F(Cli, ClassifyEmptyPointsFileWritesNothing) {
  Result r = run("classify " + data("hexagon.txt") + " " + data("points_empty.txt"));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "");
}

TEST_F(Cli, ClassifyReadsStandardInputRedirectedAndPiped) {
  const std::string expected = slurp(kData + "/hexagon_expected.txt");
  Result redirected = run("classify " + data("hexagon.txt") + " - < " + data("hexagon_points.txt"));
  EXPECT_EQ(redirected.code, 0) << redirected.err;
  EXPECT_EQ(redirected.out, expected);
  Result piped = run("classify " + data("hexagon.txt") + " -", "cat " + data("hexagon_points.txt"));
  EXPECT_EQ(piped.code, 0) << piped.err;
  EXPECT_EQ(piped.out, expected);
  Result shapeIn = run("classify - " + data("hexagon_points.txt"), "cat " + data("hexagon.txt"));
  EXPECT_EQ(shapeIn.code, 0) << shapeIn.err;
  EXPECT_EQ(shapeIn.out, expected);
}

// === classify: rejections of bad input (exit 1, FILE:LINE: problem, empty stdout)

TEST_F(Cli, ClassifyRejectsBadPolygons) {
  const Rejection cases[] = {
      {"polygon_reflex.txt", "polygon_reflex.txt:5: not convex: reflex vertex 4 (2, 1)"},
      {"polygon_bowtie.txt", "polygon_bowtie.txt:4: self-intersecting: the edge from vertex 1"},
      {"polygon_pentagram.txt", "polygon_pentagram.txt:6: self-intersecting"},
      {"polygon_doubles_back.txt", "polygon_doubles_back.txt:3: the boundary doubles back"},
      {"polygon_collinear.txt", "polygon_collinear.txt:5: all 4 vertices are collinear"},
      {"polygon_two_distinct.txt", "polygon_two_distinct.txt:5: fewer than 3 distinct vertices"},
      {"polygon_two_vertices.txt",
       "polygon_two_vertices.txt:3: a polygon needs at least 3 vertices, got 2"},
      {"polygon_empty.txt", "polygon_empty.txt: no vertices"},
      {"polygon_nan.txt", "polygon_nan.txt:3: not a number: 'nan'"},
      {"polygon_inf.txt", "polygon_inf.txt:4: not a number: 'inf'"},
      {"polygon_hex_number.txt", "polygon_hex_number.txt:3: not a number: '0x10'"},
      {"polygon_huge_number.txt",
       "polygon_huge_number.txt:4: number out of the range of double: '1e400'"},
      {"polygon_one_number.txt", "polygon_one_number.txt:3: expected 2 numbers, found 1"},
      {"polygon_three_numbers.txt", "polygon_three_numbers.txt:2: expected 2 numbers, found more"},
      {"polygon_garbage.txt", "polygon_garbage.txt:1: not a number: '\\x89PNG'"},
      {"polygon_words.txt", "polygon_words.txt:2: not a number: 'zero'"},
  };
  for (const Rejection& c : cases) {
    SCOPED_TRACE(c.file);
    for (const char* m : {"halfplane", "polar"})
      expectRejected(
          run("classify " + data(c.file) + " " + data("hexagon_points.txt") + " -m " + m),
          c.message);
  }
}

TEST_F(Cli, ClassifyRejectsBadPoints) {
  const Rejection cases[] = {
      {"points_bad_line_late.txt",
       "points_bad_line_late.txt:5002: unexpected text after 2 numbers: 'oops'"},
      {"points_wrong_count.txt", "points_wrong_count.txt:4: expected 2 numbers, found more"},
      {"points_inf.txt", "points_inf.txt:3: not a number: '-inf'"},
      {"polygon_garbage.txt", "polygon_garbage.txt:1: not a number"},
  };
  for (const Rejection& c : cases) {
    SCOPED_TRACE(c.file);
    expectRejected(run("classify " + data("hexagon.txt") + " " + data(c.file)), c.message);
  }
}

TEST_F(Cli, ClassifyBadLineLateOnStandardInputWritesNothing) {
  expectRejected(
      run("classify " + data("hexagon.txt") + " -", "cat " + data("points_bad_line_late.txt")),
      "<stdin>:5002: unexpected text after 2 numbers");
  expectRejected(
      run("classify " + data("hexagon.txt") + " - < " + data("points_bad_line_late.txt")),
      "<stdin>:5002: unexpected text after 2 numbers");
}

TEST_F(Cli, ClassifyBadLineAfterMegabytesOfAnswersWritesNothing) {
  // 300000 good points (several MB of answers, more than any output buffer) then a bad line
  const std::string shape = data("hexagon.txt");
  const std::string points =
      runTo("generate points --shape " + shape + " --count 300000 --seed 5", "many.txt");
  std::ofstream(points, std::ios::app) << "1 2 3\n";
  expectRejected(run("classify " + shape + " " + q(points)), "many.txt:300002: expected 2 numbers");
  expectRejected(run("classify " + shape + " -", "cat " + q(points)),
                 "<stdin>:300002: expected 2 numbers");
}

TEST_F(Cli, ClassifyRejectsMissingFilesAndDirectories) {
  expectRejected(run("classify " + data("no_such_polygon.txt") + " " + data("hexagon_points.txt")),
                 "no_such_polygon.txt: cannot open: No such file or directory");
  expectRejected(run("classify " + data("hexagon.txt") + " " + data("no_such_points.txt")),
                 "no_such_points.txt: cannot open: No such file or directory");
  expectRejected(run("classify " + q(kData) + " " + data("hexagon_points.txt")),
                 "cannot open: it is a directory");
  expectRejected(run("classify " + data("hexagon.txt") + " " + q(kData)),
                 "cannot open: it is a directory");
}

TEST_F(Cli, ClassifyPolyhedronWantsThreeNumbersPerPoint) {
  // a .off shape is a polyhedron: a polygon's points file is bad input for it
  expectRejected(run("classify " + data("shape_polyhedron.off") + " " + data("hexagon_points.txt")),
                 "hexagon_points.txt:2: expected 3 numbers, found 2");
}

// === bad usage (exit 2, usage on stderr, nothing on stdout)

TEST_F(Cli, BadUsageExitsTwoWithUsage) {
  const std::string shape = data("hexagon.txt"), points = data("hexagon_points.txt");
  expectUsage(run(""), "subcommand is required");
  expectUsage(run("frobnicate"));
  expectUsage(run("classify"), "SHAPE is required");
  expectUsage(run("classify " + shape), "POINTS is required");
  expectUsage(run("classify " + shape + " " + points + " --bogus"), "--bogus");
  expectUsage(run("classify " + shape + " " + points + " extra"));
  expectUsage(run("classify " + shape + " " + points + " --method octree"),
              "unknown method 'octree'");
  expectUsage(run("classify " + shape + " " + points + " --method"));
  expectUsage(run("classify " + shape + " " + points + " --resolution -4"), "--resolution");
  expectUsage(run("classify " + shape + " " + points + " --resolution many"), "--resolution");
  expectUsage(run("classify " + shape + " " + points + " --resolution 99999999999"),
              "--resolution");
  expectUsage(run("classify " + shape + " " + points + " -m polar --resolution 100000000"),
              "at most");
  expectUsage(run("classify - -"), "standard input");
  expectUsage(run("info"), "SHAPE is required");
  expectUsage(run("info " + shape + " --method nope"), "unknown method 'nope'");
  expectUsage(run("generate"), "subcommand is required");
  expectUsage(run("generate polygon"), "--kind is required");
  expectUsage(run("generate polygon --kind blob"), "unknown polygon kind 'blob'");
  expectUsage(run("generate polygon --kind regular --n 2"), "at least 3");
  expectUsage(run("generate polygon --kind regular --n -5"), "--n");
  expectUsage(run("generate polygon --kind regular --seed 18446744073709551616"), "--seed");
  expectUsage(run("generate points"), "--shape is required");
  expectUsage(run("generate points --shape " + shape + " --count -1"), "--count");
}

TEST_F(Cli, HelpAndVersionGoToStdoutAndExitZero) {
  for (const char* args : {"--help", "classify --help", "info -h", "generate polygon --help",
                           "generate polyhedron --help", "generate points --help"}) {
    Result r = run(args);
    EXPECT_EQ(r.code, 0) << args;
    EXPECT_NE(r.out.find("Usage:"), std::string::npos) << args;
    EXPECT_EQ(r.err, "") << args;
  }
  Result v = run("--version");
  EXPECT_EQ(v.code, 0);
  EXPECT_EQ(v.out.rfind("convexloc ", 0), 0u) << v.out;
}

// === info

TEST_F(Cli, InfoTableShowsEveryMethod) {
  Result r = run("info " + data("hexagon.txt"));
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* m : kMethods)
    EXPECT_NE(r.out.find(std::string("  ") + m + " "), std::string::npos) << m;
  for (const char* key : {"6 kept of 6 read", "counter-clockwise", "area              12", "cells",
                          "entries", "bytes/edge", "build"})
    EXPECT_NE(r.out.find(key), std::string::npos) << key << " in\n" << r.out;
}

TEST_F(Cli, InfoOneMethodInDetail) {
  Result r = run("info " + data("hexagon_clockwise_crlf.txt") + " --method polar --resolution 3");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* key :
       {"6 kept of 8 read", "dropped           1 repeated, 1 on an edge", "clockwise in the file",
        "Method polar", "centre", "slabs per octant  3 (24 cells)", "cells             24",
        "edges per cell    max", "crowded cells", "bytes per edge", "build time",
        "edges per cell    cells"})
    EXPECT_NE(r.out.find(key), std::string::npos) << key << " in\n" << r.out;
  Result u = run("info " + data("hexagon.txt") + " -m uniform -r 5");
  ASSERT_EQ(u.code, 0) << u.err;
  EXPECT_NE(u.out.find("slabs             5"), std::string::npos) << u.out;
  Result h = run("info " + data("hexagon.txt") + " -m halfplane");
  ASSERT_EQ(h.code, 0) << h.err;
  EXPECT_NE(h.out.find("none"), std::string::npos) << h.out;
}

TEST_F(Cli, InfoRejectsBadPolygons) {
  expectRejected(run("info " + data("polygon_reflex.txt")), "polygon_reflex.txt:5: not convex");
  expectRejected(run("info " + data("polygon_empty.txt")), "no vertices");
  // a .off shape is a polyhedron, reported as one
  Result r = run("info " + data("shape_polyhedron.off"));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("Polyhedron\n"), std::string::npos) << r.out;
}

// the "bytes/edge" column of an info table, one value per method
std::vector<double> bytesPerEdge(const std::string& table) {
  std::vector<double> out;
  for (const std::string& line : linesOf(table)) {
    std::istringstream in(line);
    std::string method;
    in >> method;
    bool known = false;
    for (const char* m : kMethods) known = known || method == m;
    if (!known) continue;
    // method query cells entries max mean crowded bytes bytes/edge build unit
    std::vector<std::string> f;
    for (std::string w; in >> w;) f.push_back(w);
    if (f.size() >= 9) out.push_back(std::stod(f[f.size() - 3]));
  }
  return out;
}

TEST_F(Cli, InfoTinyEdgesAtMostSixtyFourBytesPerEdge) {
  for (const char* n : {"64", "1000", "20000"}) {
    const std::string shape = runTo("generate polygon --kind tiny-edges --n " + std::string(n),
                                    std::string("tiny-") + n + ".txt");
    Result r = run("info " + q(shape));
    ASSERT_EQ(r.code, 0) << r.err;
    auto b = bytesPerEdge(r.out);
    ASSERT_EQ(b.size(), 5u) << r.out;
    for (double v : b) EXPECT_LE(v, 64.0) << "n = " << n << "\n" << r.out;
    Result detail = run("info " + q(shape) + " --method polar");
    EXPECT_NE(detail.out.find("bytes per edge"), std::string::npos);
  }
}

// === generate

TEST_F(Cli, GeneratedPolygonVerticesAreAllBoundary) {
  for (const char* kind : kKinds) {
    SCOPED_TRACE(kind);
    const std::string shape =
        runTo(std::string("generate polygon --kind ") + kind + " --n 50 --seed 3", "shape.txt");
    const std::string text = slurp(shape);
    ASSERT_EQ(text.rfind("# convexloc generate polygon --kind ", 0), 0u) << text;
    const std::size_t vertices = dataLines(text).size();
    ASSERT_GE(vertices, 3u);
    for (const char* m : kMethods) {
      Result r = run("classify " + q(shape) + " " + q(shape) + " -m " + m);
      ASSERT_EQ(r.code, 0) << m << ": " << r.err;
      auto answers = linesOf(r.out);
      ASSERT_EQ(answers.size(), vertices) << m;
      for (const auto& a : answers) EXPECT_EQ(a, "boundary") << m;
    }
  }
}

TEST_F(Cli, GeneratePolygonIsDeterministic) {
  Result a = run("generate polygon --kind random --n 40 --seed 9");
  Result b = run("generate polygon --kind random --n 40 --seed 9");
  Result c = run("generate polygon --kind random --n 40 --seed 10");
  EXPECT_EQ(a.code, 0);
  EXPECT_EQ(a.out, b.out);
  EXPECT_NE(dataLines(a.out), dataLines(c.out));
}

TEST_F(Cli, GeneratePointsCountAndDeterminism) {
  const std::string shape = data("hexagon.txt");
  for (const char* count : {"0", "1", "1000", "70000"}) {
    Result r = run("generate points --shape " + shape + " --count " + count + " --seed 4");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(dataLines(r.out).size(), std::stoul(count));
  }
  Result a = run("generate points --shape " + shape + " --count 500 --seed 4 --near-boundary");
  Result b = run("generate points --shape " + shape + " --count 500 --seed 4 --near-boundary");
  Result c = run("generate points --shape " + shape + " --count 500 --seed 5 --near-boundary");
  EXPECT_EQ(a.out, b.out);
  EXPECT_NE(dataLines(a.out), dataLines(c.out));
}

TEST_F(Cli, GeneratedPointsClassifyAlikeWithEveryMethod) {
  for (const char* kind : {"random", "sliver", "tiny-edges", "offset", "degenerate"}) {
    SCOPED_TRACE(kind);
    const std::string shape =
        runTo(std::string("generate polygon --kind ") + kind + " --n 200 --seed 2", "shape.txt");
    const std::string points =
        runTo("generate points --shape " + q(shape) + " --count 20000 --seed 8 --near-boundary",
              "points.txt");
    std::string first;
    for (const char* m : kMethods) {
      Result r = run("classify " + q(shape) + " " + q(points) + " -m " + m);
      ASSERT_EQ(r.code, 0) << r.err;
      EXPECT_EQ(linesOf(r.out).size(), 20000u);
      if (first.empty())
        first = r.out;
      else
        EXPECT_EQ(r.out, first) << m << " disagrees with halfplane";
    }
    // near-boundary points are hard cases: all three answers occur
    for (const char* a : {"inside\n", "boundary\n", "outside\n"})
      EXPECT_NE(first.find(a), std::string::npos) << a;
  }
}

TEST_F(Cli, ClassifyStreamsAPipeOfManyPoints) {
  const std::string shape = data("hexagon.txt");
  Result r = run("classify " + shape + " -",
                 q(kBin) + " generate points --shape " + shape + " --count 250000 --seed 1");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(linesOf(r.out).size(), 250000u);
}

// === the shipped examples

TEST_F(Cli, ShippedExamplesWork) {
  Result r =
      run("classify " + q(kAssets + "/hexagon.txt") + " " + q(kAssets + "/hexagon-points.txt"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out,
            "inside\ninside\nboundary\nboundary\nboundary\nboundary\nboundary\ninside\noutside\n"
            "outside\noutside\noutside\n");
  for (const char* f : {"square.txt", "random-12.txt", "tiny-edges.txt", "hexagon.txt"}) {
    Result i = run("info " + q(kAssets + "/" + f));
    EXPECT_EQ(i.code, 0) << f << ": " << i.err;
  }
}

}  // namespace
