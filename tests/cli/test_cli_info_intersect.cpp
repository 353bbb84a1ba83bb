// `convexloc info` on the line and plane methods of `intersect`: the section after the
// point-location table, its exact sizes and counts (never its times), when the polyhedron's
// dual is built, and that the report before it is left as it was.
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "cli_run.hpp"

namespace {

using namespace cli_test;

// the words of the row of `method` in the section titled `title`, empty when absent
std::vector<std::string> rowWords(const std::string& report, const std::string& title,
                                  const std::string& method) {
  const std::size_t at = report.find("\n" + title + "\n");
  if (at == std::string::npos) return {};
  for (const std::string& line : linesOf(report.substr(at + 1))) {
    if (line.rfind("  " + method + " ", 0) != 0) continue;
    std::istringstream in(line);
    std::vector<std::string> words;
    for (std::string w; in >> w;) words.push_back(w);
    return words;
  }
  return {};
}

const std::string kLines =
    "Line methods (convexloc intersect: misses, touches or crosses the polygon)";
const std::string kPlanes =
    "Plane methods (convexloc intersect: misses, touches or crosses the polyhedron)";
const std::string kHeader2D =
    "  method     query     dual size    cells   entries   max        bytes  bytes/edge      "
    "build\n";
const std::string kHeader3D =
    "  method     query     dual size    cells   entries   max        bytes  bytes/face      "
    "build\n";

// the words before the build time: method, cost, dual size, cells, entries, max, bytes,
// bytes per edge (face)
std::vector<std::string> withoutTime(std::vector<std::string> words) {
  if (words.size() >= 2) words.resize(words.size() - 2);  // "20.4 us"
  return words;
}

using Words = std::vector<std::string>;

TEST_F(Cli, InfoTableEndsWithTheLineMethods) {
  Result r = run("info " + q(kAssets + "/hexagon.txt"));
  ASSERT_EQ(r.code, 0) << r.err;
  // the point-location report comes first, unchanged up to its last line
  const std::size_t section = r.out.find("\n" + kLines + "\n");
  ASSERT_NE(section, std::string::npos) << r.out;
  EXPECT_EQ(r.out.substr(0, section + 1).rfind("  convexloc info SHAPE --method polar\n\n"),
            section + 1 - std::string("  convexloc info SHAPE --method polar\n\n").size())
      << r.out;
  EXPECT_NE(r.out.find(kLines + "\n" + kHeader2D), std::string::npos) << r.out;
  // six vertices of 16 bytes; the dual of a centrally symmetric hexagon has its 6 normals
  EXPECT_EQ(withoutTime(rowWords(r.out, kLines, "vertices")),
            (Words{"vertices", "O(N)", "-", "-", "-", "-", "96", "16.0"}));
  EXPECT_EQ(withoutTime(rowWords(r.out, kLines, "bisection")),
            (Words{"bisection", "O(log", "N)", "-", "-", "-", "-", "96", "16.0"}));
  const Words dual = withoutTime(rowWords(r.out, kLines, "dual"));
  ASSERT_EQ(dual.size(), 8u) << r.out;
  EXPECT_EQ((Words{dual.begin(), dual.begin() + 6}), (Words{"dual", "O(1)", "6", "64", "76", "2"}));
  // bytes per edge is the memory over the six edges
  EXPECT_NEAR(std::stod(dual[7]), std::stod(dual[6]) / 6, 0.05) << r.out;
  EXPECT_NE(r.out.find("\nEvery method decides exactly"), std::string::npos) << r.out;
}

TEST_F(Cli, InfoOneMethodShowsTheLineMethodsOnlyWhenAsked) {
  Result plain = run("info " + q(kAssets + "/hexagon.txt") + " --method polar");
  ASSERT_EQ(plain.code, 0) << plain.err;
  EXPECT_EQ(plain.out.find(kLines), std::string::npos) << plain.out;
  Result asked = run("info " + q(kAssets + "/hexagon.txt") + " --method polar --intersect");
  ASSERT_EQ(asked.code, 0) << asked.err;
  EXPECT_EQ(asked.out.rfind(plain.out.substr(0, plain.out.find("  build time")), 0), 0u);
  EXPECT_EQ(withoutTime(rowWords(asked.out, kLines, "dual")).size(), 8u) << asked.out;
}

TEST_F(Cli, InfoBuildsThePolyhedronsDualOnlyWithIntersect) {
  Result r = run("info " + data("cube3d.off"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find(kPlanes + "\n" + kHeader3D), std::string::npos) << r.out;
  EXPECT_EQ(withoutTime(rowWords(r.out, kPlanes, "vertices")),
            (Words{"vertices", "O(V)", "-", "-", "-", "-", "192", "16.0"}));
  EXPECT_NE(r.out.find("\n  dual       O(1)      not built: add --intersect"), std::string::npos)
      << r.out;

  Result asked = run("info " + data("cube3d.off") + " --intersect");
  ASSERT_EQ(asked.code, 0) << asked.err;
  // the cube's dual is the octahedron: 8 triangles, listed by a cube map of 6 x 8 x 8 cells
  // (the smallest default, 16, halved to fit the constant budget with every cell's slab)
  const Words dual = withoutTime(rowWords(asked.out, kPlanes, "dual"));
  ASSERT_EQ(dual.size(), 8u) << asked.out;
  EXPECT_EQ((Words{dual.begin(), dual.begin() + 6}),
            (Words{"dual", "O(1)", "8", "384", "600", "4"}));
  // bytes per face is the memory over the cube's 12 triangles
  EXPECT_NEAR(std::stod(dual[7]), std::stod(dual[6]) / 12, 0.05) << asked.out;
  EXPECT_EQ(asked.out.find("edges"), std::string::npos) << "a polyhedron's report counts faces";
}

TEST_F(Cli, InfoIntersectOnBadInputWritesNothing) {
  expectRejected(run("info " + data("polygon_reflex.txt") + " --intersect"),
                 "polygon_reflex.txt:5: not convex");
  expectUsage(run("info " + data("hexagon.txt") + " --intersect=maybe"));
}

}  // namespace

// the dual's work measured on random queries: a sentence under each dimension's table
TEST_F(Cli, InfoMeasuresTheDualsWorkPerQuery) {
  Result r = run("info " + q(kAssets + "/hexagon.txt"));
  ASSERT_EQ(r.code, 0) << r.err;
  const std::size_t at = r.out.find("The dual, on 1000 random lines through the enlarged bounding");
  ASSERT_NE(at, std::string::npos) << r.out;
  // both extremes confirmed, each with at least two exact comparisons
  double comparisons = 0, moves = 0;
  ASSERT_EQ(std::sscanf(r.out.c_str() + r.out.find("box: ", at),
                        "box: %lf exact\ncomparisons and %lf", &comparisons, &moves),
            2)
      << r.out;
  EXPECT_GE(comparisons, 4.0);
  EXPECT_LT(moves, 2.0);
  Result planes = run("info " + data("cube3d.off") + " --intersect");
  ASSERT_EQ(planes.code, 0) << planes.err;
  EXPECT_NE(planes.out.find("The dual, on 1000 random planes"), std::string::npos) << planes.out;
  Result unbuilt = run("info " + data("cube3d.off"));
  EXPECT_EQ(unbuilt.out.find("random planes"), std::string::npos) << unbuilt.out;
}
