// Hostile mesh files for the core's OFF and OBJ readers and for ConvexPolyhedron: headers
// that announce absurd counts (refused before any allocation), references past the end,
// lines at and past the limit, the last line filling the reader's buffer, binary garbage.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/generate2d.hpp"
#include "convexloc/mesh_reader.hpp"
#include "convexloc/polyhedron.hpp"
#include "convexloc/text_reader.hpp"
#include "fuzz_support.hpp"
#include "tool.hpp"

namespace {

using convexloc::ConvexPolyhedron;
using convexloc::MeshData;
using convexloc::MeshFormat;
using convexloc::ParseError;
using convexloc::Vec3;

// what reading a mesh gave: the error's line and message, or none
struct Outcome {
  std::optional<MeshData> mesh;
  std::size_t line = 0;
  std::string error;
  double seconds = 0;
};

// reads `text` as OFF or OBJ through a FILE, as the tool does
Outcome read(const std::string& text, bool off) {
  std::FILE* f = fmemopen(const_cast<char*>(text.data()), text.size(), "rb");
  Outcome out;
  auto t0 = std::chrono::steady_clock::now();
  try {
    out.mesh = convexloc::parseMesh(off ? MeshFormat::Off : MeshFormat::Obj, f);
  } catch (const ParseError& e) {
    out.line = e.line();
    out.error = e.what();
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::fclose(f);
  return out;
}

void expectError(const Outcome& o, std::size_t line, const std::string& message) {
  EXPECT_FALSE(o.mesh.has_value()) << "accepted; expected: " << message;
  EXPECT_EQ(o.line, line) << o.error;
  EXPECT_NE(o.error.find(message), std::string::npos) << o.error;
}

const std::string kTetraFaces = "3 0 1 2\n3 0 2 3\n3 0 3 1\n3 1 3 2\n";

// === Counts in headers are limits checked, never allocations

TEST(HostileMesh, AbsurdHeaderCountsFailFastWithoutAllocating) {
  const long before = hostile::peakKiB();
  auto t0 = std::chrono::steady_clock::now();
  expectError(read("OFF\n4 1000000000000 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n" + kTetraFaces, true), 2,
              "announces 1000000000000 faces; at most 134217728 are supported");
  expectError(read("OFF 99999999999999999999999 4 0\n", true), 1, "");
  expectError(read("OFF\n1000000000000 4\n0 0 0\n", true), 2, "1000000000000 vertices");
  expectError(read("OFF\n-4 4\n", true), 2, "not a non-negative integer");
  // within the limit but far more than the file holds: it ends early, nothing was reserved
  expectError(read("OFF\n4 100000000 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n" + kTetraFaces, true), 10,
              "the file ends after 4 of the 100000000 faces");
  expectError(read("OFF\n134217728 4 0\n0 0 0\n", true), 3, "the file ends after 1 of the");
  // a face announcing a billion vertices
  expectError(read("OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1000000000 0 1 2\n", true), 7,
              "the face announces 1000000000 vertices but lists 3");
  // OBJ references far past the end, or before the first vertex
  expectError(read("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 1000000000000\n", false), 4, "out of range");
  expectError(read("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -99999999999\n", false), 4,
              "before the first vertex");
  expectError(read("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", false), 4, "out of range");
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_LT(seconds, 1.0);
  EXPECT_LT(hostile::peakKiB() - before, 16 * 1024) << "a count in a header was used to allocate";
}

// === Lines

// "x y z" padded with blanks to exactly `length` bytes
std::string vertexLine(const std::string& xyz, std::size_t length) {
  std::string s = xyz.substr(0, xyz.rfind(' '));
  s.append(length - xyz.size(), ' ');
  return s + xyz.substr(xyz.rfind(' '));
}

TEST(HostileMesh, TheLineLimitIsExact) {
  using convexloc::kMaxLineBytes;
  for (const char* end : {"\n", "\r\n"}) {
    SCOPED_TRACE(end[0] == '\r' ? "CRLF" : "LF");
    std::string head = std::string("OFF") + end + "4 4 0" + end;
    std::string rest = std::string("1 0 0") + end + "0 1 0" + end + "0 0 1" + end;
    Outcome at = read(head + vertexLine("0 0 0", kMaxLineBytes) + end + rest + kTetraFaces, true);
    EXPECT_TRUE(at.mesh.has_value()) << at.error;
    Outcome past =
        read(head + vertexLine("0 0 0", kMaxLineBytes + 1) + end + rest + kTetraFaces, true);
    expectError(past, 3, "line longer than 1048576 bytes");
    Outcome obj = read(vertexLine("v 0 0 0", kMaxLineBytes + 1) + end, false);
    expectError(obj, 1, "line longer than 1048576 bytes");
  }
}

// Regression: a last line without a newline that exactly fills the reader's buffer made the
// mesh reader read freed memory (the same fault as RowReader's; see test_hostile_core2d.cpp).
TEST(HostileMesh, ALastLineFillingTheBufferIsRead) {
  const std::string off = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n";
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\n";
  for (std::size_t size = std::size_t{1} << 15; size <= (std::size_t{1} << 20); size *= 2)
    for (std::size_t delta : {0, 1}) {
      SCOPED_TRACE(std::to_string(size - delta) + " bytes");
      std::string lastOff = "3 1 2";
      lastOff.append(size - delta - 6, ' ').append("3");
      std::string lastObj = "f 2 3";
      lastObj.append(size - delta - 7, ' ').append(" 4");
      // alone (the buffer then holds the whole tail) and after the others
      for (bool alone : {false, true}) {
        Outcome o = read(alone ? lastOff : off + lastOff, true);
        Outcome j = read(alone ? lastObj : obj + lastObj, false);
        if (alone) continue;  // not a valid file, but read without a fault
        EXPECT_EQ(o.mesh ? o.mesh->faceCount() : 0, 4u) << o.error;
        EXPECT_EQ(j.mesh ? j.mesh->faceCount() : 0, 4u) << j.error;
      }
    }
}

// === Garbage

// OFF rejects garbage as a ParseError; OBJ ignores the statements it does not know, so
// garbage reads as an empty or broken mesh that validation rejects.
TEST(HostileMesh, BinaryGarbageIsRejected) {
  convexloc::Rng rng(66);
  for (int round = 0; round < 6; ++round) {
    std::string bytes(std::size_t{1} << (10 + 2 * round), '\0');
    for (char& c : bytes) c = static_cast<char>(rng.next());
    for (bool off : {true, false}) {
      std::string text = off && round % 2 ? "OFF\n" : "";
      text.append(bytes);
      Outcome o = read(text, off);
      if (o.mesh) {
        EXPECT_FALSE(off) << "OFF accepted garbage";
        EXPECT_THROW(ConvexPolyhedron{*o.mesh}, convexloc::GeometryError);
        continue;
      }
      EXPECT_FALSE(o.error.empty());
      for (char c : o.error) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << o.error;
    }
  }
}

}  // namespace
