// Hostile and huge polyhedron inputs to the real `convexloc` binary: absurd OFF headers,
// garbage meshes, a polyhedron of a million faces, ten million 3D points streamed.
#include <gtest/gtest.h>

#include <array>
#include <charconv>
#include <cmath>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "convexloc/generate2d.hpp"
#include "convexloc/mesh_reader.hpp"
#include "convexloc/polyhedron.hpp"
#include "fuzz_support.hpp"
#include "tool.hpp"

namespace {

using convexloc::Vec3;
using hostile::runTool;
using hostile::TempDir;
using hostile::ToolRun;
using hostile::writeFile;

const char* const kMethods3D[] = {"halfspace", "walk", "cubemap"};
const std::string kCube =
    "OFF\n8 6 0\n-1 -1 -1\n1 -1 -1\n-1 1 -1\n1 1 -1\n-1 -1 1\n1 -1 1\n-1 1 1\n1 1 1\n"
    "4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n";

// a clean rejection naming FILE:LINE (or FILE: for line 0)
void expectRejected(const ToolRun& r, const std::string& file, std::size_t line,
                    const std::string& message) {
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_EQ(r.outBytes, 0u);
  std::string where = file;
  if (line) where.append(":").append(std::to_string(line));
  where.append(": ");
  EXPECT_EQ(r.err.rfind(where, 0), 0u) << r.err;
  EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
  EXPECT_LT(r.err.size(), 400u) << r.err;
}

TEST(HostileCli3D, AnOffHeaderAnnouncingATrillionFacesFailsFast) {
  TempDir dir;
  writeFile(dir.file("points.txt"), "0 0 0\n");
  writeFile(dir.file("huge.off"), "OFF\n8 1000000000000 0\n-1 -1 -1\n1 -1 -1\n");
  ToolRun r = runTool({"classify", dir.file("huge.off"), dir.file("points.txt")});
  expectRejected(r, dir.file("huge.off"), 2,
                 "announces 1000000000000 faces; at most 134217728 are supported");
  EXPECT_LT(r.seconds, 2.0);
  // within the limit, but the file holds far fewer: it ends early, nothing was reserved
  writeFile(dir.file("short.off"), "OFF\n8 100000000 0\n" + kCube.substr(kCube.find("-1 -1 -1")));
  r = runTool({"classify", dir.file("short.off"), dir.file("points.txt")});
  expectRejected(r, dir.file("short.off"), 16, "the file ends after 6 of the 100000000 faces");
  EXPECT_LT(r.maxRssKiB, 64 * 1024) << "a count in a header was used to allocate";
  r = runTool({"info", dir.file("huge.off")});
  EXPECT_EQ(r.status, 1) << r.err;
}

TEST(HostileCli3D, GarbageMeshesAreRejectedCleanly) {
  TempDir dir;
  writeFile(dir.file("points.txt"), "0 0 0\n");
  convexloc::Rng rng(3);
  for (const char* ext : {".off", ".obj"})
    for (int round = 0; round < 4; ++round) {
      std::string bytes(std::size_t{1} << (12 + 2 * round), '\0');
      for (char& c : bytes) c = static_cast<char>(rng.next());
      std::string path = dir.file(std::string("garbage") + ext);
      writeFile(path, bytes);
      ToolRun r = runTool({"classify", path, dir.file("points.txt")});
      SCOPED_TRACE(path + " round " + std::to_string(round));
      EXPECT_EQ(r.status, 1) << r.err;
      EXPECT_EQ(r.outBytes, 0u);
      EXPECT_EQ(r.err.rfind(path, 0), 0u) << r.err;
      for (char c : r.err) EXPECT_TRUE(c == '\n' || (c >= 0x20 && c < 0x7f)) << r.err;
    }
  // a 2D polygon named .off, and a mesh that is not closed
  writeFile(dir.file("square.off"), "0 0\n1 0\n1 1\n0 1\n");
  EXPECT_EQ(runTool({"classify", dir.file("square.off"), dir.file("points.txt")}).status, 1);
  writeFile(dir.file("open.off"),
            "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n");
  ToolRun r = runTool({"classify", dir.file("open.off"), dir.file("points.txt")});
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_EQ(r.err.rfind(dir.file("open.off") + ":", 0), 0u) << r.err;
}

// Writes `count` 3D points that cycle through inside, boundary and outside of the cube.
std::function<bool(std::string&)> cyclingPoints3D(std::size_t count) {
  return [count, i = std::size_t{0}](std::string& buf) mutable {
    static const char* const kCycle[] = {"0.5 0.25 -0.5\n", "1 0.75 0\n", "2.5,-1,0\n"};
    for (int k = 0; k < 4096 && i < count; ++k, ++i) buf += kCycle[i % 3];
    return i < count;
  };
}

TEST(HostileCli3D, TenMillionPointsStreamInConstantMemory) {
  const std::size_t n = hostile::scaled(10'000'000, 100'000);
  TempDir dir;
  writeFile(dir.file("cube.off"), kCube);
  writeFile(dir.file("few.txt"), "0.5 0.25 -0.5\n1 0.75 0\n2.5,-1,0\n");
  hostile::writeBig(dir.file("many.txt"), cyclingPoints3D(n));
  ToolRun few = runTool({"classify", dir.file("cube.off"), dir.file("few.txt")});
  ASSERT_EQ(few.status, 0) << few.err;
  EXPECT_EQ(few.out, "inside\nboundary\noutside\n");
  hostile::Options count;
  count.keepOut = false;
  for (const char* m : kMethods3D) {
    ToolRun many =
        runTool({"classify", dir.file("cube.off"), dir.file("many.txt"), "--method", m}, count);
    ASSERT_EQ(many.status, 0) << many.err;
    EXPECT_EQ(many.answers[0], (n + 2) / 3) << m;
    EXPECT_EQ(many.answers[1], (n + 1) / 3) << m;
    EXPECT_EQ(many.answers[2], n / 3) << m;
    std::printf("[ figures  ] %zu 3D points, %-9s %.2f s, peak memory %ld KiB (%ld KiB for 3)\n", n,
                m, many.seconds, many.maxRssKiB, few.maxRssKiB);
    EXPECT_LT(many.maxRssKiB, few.maxRssKiB + hostile::constantMemorySlackKiB())
        << "memory grew with the points";
  }
}

TEST(HostileCli3D, AMillionFaces) {
  // a geodesic sphere of about 10^6 triangles from the tool's own generator
  const std::size_t n = hostile::scaled(1'000'000, 100'000);
  TempDir dir;
  hostile::Options toFile;
  toFile.stdoutPath = dir.file("sphere.off");
  ToolRun gen =
      runTool({"generate", "polyhedron", "--kind", "geodesic", "--n", std::to_string(n)}, toFile);
  ASSERT_EQ(gen.status, 0) << gen.err;
  // the centre and points well inside and outside the unit sphere
  writeFile(dir.file("points.txt"), "0 0 0\n0.5 0.5 0.5\n2 0 0\n0 0 -1.5\n0.9 0 0\n");
  for (const char* m : kMethods3D) {
    ToolRun r =
        runTool({"classify", dir.file("sphere.off"), dir.file("points.txt"), "--method", m});
    EXPECT_EQ(r.status, 0) << m << ": " << r.err;
    EXPECT_EQ(r.out, "inside\ninside\noutside\noutside\ninside\n") << m;
    std::printf(
        "[ figures  ] geodesic sphere of ~%zu faces, %-9s classify %.2f s, peak memory "
        "%ld MiB\n",
        n, m, r.seconds, r.maxRssKiB / 1024);
  }
  ToolRun info = runTool({"info", dir.file("sphere.off"), "--method", "cubemap"});
  EXPECT_EQ(info.status, 0) << info.err;
  std::printf("[ figures  ] generated in %.2f s; info --method cubemap:\n%s\n", gen.seconds,
              info.out.c_str());
}

}  // namespace
