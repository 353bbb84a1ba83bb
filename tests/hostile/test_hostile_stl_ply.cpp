// Hostile STL and PLY files for the core's readers: cut at every byte, counts that lie, NaN
// and infinite coordinates, the wrong byte order, a billion facets claimed (refused before any
// allocation), indices out of range, non-seekable input, random garbage. Every one is a
// ParseError naming the line (text) or the byte offset (binary), the same from memory and
// through a FILE, and never a crash.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/generate2d.hpp"
#include "convexloc/mesh_reader.hpp"
#include "convexloc/polyhedron.hpp"
#include "fuzz_support.hpp"
#include "mesh_bytes.hpp"
#include "shapes3d.hpp"
#include "tool.hpp"

namespace {

using convexloc::MeshData;
using convexloc::MeshFormat;
using convexloc::ParseError;
using convexloc::PlyEncoding;
using convexloc::Vec3;

// what reading gave: a mesh, or the error's line and message
struct Outcome {
  std::optional<MeshData> mesh;
  std::size_t line = 0;
  std::string error;
};

// reads `bytes` as STL (or PLY) from memory and through a FILE, which must agree
Outcome read(const std::string& bytes, bool stl) {
  auto attempt = [&](auto&& parse) {
    Outcome o;
    try {
      o.mesh = parse();
    } catch (const ParseError& e) {
      o.line = e.line();
      o.error = e.what();
    }
    return o;
  };
  Outcome memory =
      attempt([&] { return convexloc::parseMesh(stl ? MeshFormat::Stl : MeshFormat::Ply, bytes); });
  fuzz::MemFile file(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  Outcome viaFile = attempt(
      [&] { return convexloc::parseMesh(stl ? MeshFormat::Stl : MeshFormat::Ply, file.get()); });
  EXPECT_EQ(memory.error, viaFile.error);
  EXPECT_EQ(memory.line, viaFile.line);
  EXPECT_EQ(memory.mesh.has_value(), viaFile.mesh.has_value());
  return memory;
}

// refused, at `line`, with `message` in the text
void expectError(const Outcome& o, std::size_t line, const std::string& message) {
  EXPECT_FALSE(o.mesh.has_value()) << "accepted; expected: " << message;
  EXPECT_EQ(o.line, line) << o.error;
  EXPECT_NE(o.error.find(message), std::string::npos) << o.error;
  for (char c : o.error) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << o.error;
}

const MeshData& cube() {
  static const MeshData m = shapes3d::cube();
  return m;
}

std::string stlOf(const MeshData& m, bool ascii) {
  return meshbytes::written([&](std::FILE* f) { convexloc::writeStl(f, m, ascii); });
}

std::string plyOf(const MeshData& m, PlyEncoding enc, bool f32 = false) {
  return meshbytes::written([&](std::FILE* f) { convexloc::writePly(f, m, enc, f32); });
}

// the offset where a PLY's data starts
std::size_t dataStart(const std::string& ply) {
  return ply.find("end_header\n") + 11;
}

// === Truncation

TEST(HostileStlPly, CutAtEveryByte) {
  struct File {
    const char* name;
    std::string bytes;
    bool stl, binary;
  };
  const File files[] = {
      {"binary stl", stlOf(cube(), false), true, true},
      {"ascii stl", stlOf(cube(), true), true, false},
      {"ply ascii", plyOf(cube(), PlyEncoding::Ascii), false, false},
      {"ply le double", plyOf(cube(), PlyEncoding::BinaryLittleEndian), false, true},
      {"ply be float", plyOf(cube(), PlyEncoding::BinaryBigEndian, true), false, true}};
  for (const File& f : files) {
    SCOPED_TRACE(f.name);
    ASSERT_TRUE(read(f.bytes, f.stl).mesh.has_value());
    for (std::size_t n = 0; n < f.bytes.size(); ++n) {
      const Outcome o = read(f.bytes.substr(0, n), f.stl);
      if (!f.binary) continue;  // a text file cut at a line's end may still read
      ASSERT_FALSE(o.mesh.has_value()) << "cut at " << n << " was accepted";
      const bool inData = f.stl ? n >= 84 : n >= dataStart(f.bytes);
      if (inData) {
        EXPECT_EQ(o.error.rfind("byte ", 0), 0u) << n << ": " << o.error;
        // a binary STL's size is checked against its count first
        const char* says = f.stl ? "the header announces 12 facets" : "the file ends inside";
        EXPECT_NE(o.error.find(says), std::string::npos) << o.error;
      }
    }
  }
}

// === Counts that lie

TEST(HostileStlPly, CountsThatLie) {
  const std::string stl = stlOf(cube(), false);
  for (std::uint32_t count : {11u, 13u, 0u}) {
    std::string b = stl;
    meshbytes::Bytes c;
    c.uint(count, 4);
    b.replace(80, 4, c.s);
    expectError(read(b, true), 0,
                "byte 80: the header announces " + std::to_string(count) + " facets, which take");
  }
  // extra bytes after the facets
  expectError(read(stl + "x", true), 0, "but the file has 685 bytes");
  const std::string le = plyOf(cube(), PlyEncoding::BinaryLittleEndian);
  std::string more = le, fewer = le;
  more.replace(more.find("element face 6"), 14, "element face 7");
  expectError(read(more, false), 0, "the file ends inside face 6 of 7");
  fewer.replace(fewer.find("element face 6"), 14, "element face 5");
  expectError(read(fewer, false), 0, "unexpected bytes after the last element");
  std::string ascii = plyOf(cube(), PlyEncoding::Ascii);
  ascii.replace(ascii.find("element vertex 8"), 16, "element vertex 9");
  // the first face line is read as the ninth vertex: 5 numbers for 3 properties, and it reads
  // as a face: the count on the header's line 4 is blamed
  expectError(read(ascii, false), 4,
              "element 'vertex' announces 9 records: line 19 ('4 0 1 3 2') fails as vertex 8 of "
              "9 (unexpected text after the values of vertex 8 of 9");
}

// === Numbers

TEST(HostileStlPly, NanAndInfinityAreRefusedWhereTheyAre) {
  auto facets = meshbytes::facetsOf(cube());
  facets[3][1].y = std::numeric_limits<double>::quiet_NaN();
  expectError(
      read(meshbytes::binaryStl(facets), true), 0,
      "byte " + std::to_string(84 + 50 * 3 + 24 + 4) + ": facet 3, vertex 1: a coordinate is NaN");
  facets = meshbytes::facetsOf(cube());
  facets[11][2].z = -std::numeric_limits<double>::infinity();
  expectError(read(meshbytes::binaryStl(facets), true), 0,
              "facet 11, vertex 2: a coordinate is infinite");
  MeshData m = cube();
  m.vertices[5].x = std::numeric_limits<double>::infinity();
  const std::string be = plyOf(m, PlyEncoding::BinaryBigEndian);
  expectError(
      read(be, false), 0,
      "byte " + std::to_string(dataStart(be) + 5 * 24) + ": vertex 5: coordinate x is infinite");
  std::string ascii = plyOf(cube(), PlyEncoding::Ascii);
  ascii.replace(ascii.find("\n-1 1 -1\n") + 1, 7, "-1 nan -1");
  expectError(read(ascii, false), 13, "not a number: 'nan'");
  std::string astl = stlOf(cube(), true);
  astl.replace(astl.find("vertex -1 -1 -1"), 15, "vertex -1 -1 inf");
  expectError(read(astl, true), 4, "not a number: 'inf'");
}

TEST(HostileStlPly, TheWrongByteOrderIsNamed) {
  const std::string le = plyOf(cube(), PlyEncoding::BinaryLittleEndian);
  std::string asBig = le;
  asBig.replace(asBig.find("binary_little_endian"), 20, "binary_big_endian");
  // the doubles read as tiny numbers; the first face's indices do not
  const Outcome o = read(asBig, false);
  expectError(o, 0, "face 0: vertex index 16777216 is out of range");
  EXPECT_NE(o.error.find("read in the other byte order it would be 1"), std::string::npos);
  std::string bigFloats = plyOf(cube(), PlyEncoding::BinaryBigEndian, true);
  bigFloats.replace(bigFloats.find("binary_big_endian"), 17, "binary_little_endian");
  expectError(read(bigFloats, false), 0, "is the header's format right?");
}

// === Counts refused before anything is allocated

TEST(HostileStlPly, ABillionFacetsClaimedAllocateNothing) {
  const long before = hostile::peakKiB();
  std::string head(80, ' ');
  meshbytes::Bytes b;
  b.text(head).uint(1000000000, 4);
  expectError(read(b.s, true), 0,
              "byte 80: the header announces 1000000000 facets; at most 134217728");
  // within the limit, but the file holds none of them
  meshbytes::Bytes c;
  c.text(head).uint(134217728, 4);
  expectError(read(c.s, true), 0, "but the file has 84 bytes");
  const std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\n"
      "property float y\nproperty float z\n";
  expectError(
      read(header + "element face 1000000000\nproperty list uchar int vertex_indices\nend_header\n",
           false),
      7, "announces 1000000000 face records; at most");
  expectError(
      read("ply\nformat ascii 1.0\nelement vertex 99999999999\nproperty float x\nend_header\n",
           false),
      3, "99999999999 vertex records");
  expectError(read("ply\nformat ascii 1.0\nelement vertex -4\nend_header\n", false), 3,
              "not a non-negative integer");
  // counts in the limit on a tiny file: it ends early, nothing was reserved for them
  expectError(
      read("ply\nformat binary_little_endian 1.0\nelement vertex 134217728\nproperty float x\n"
           "property float y\nproperty float z\nelement face 134217728\n"
           "property list uint uint vertex_indices\nend_header\n0123",
           false),
      0, "the file ends inside vertex 0 of 134217728");
  // a list of four billion indices
  meshbytes::Bytes d;
  d.text(header + "element face 1\nproperty list uint int vertex_indices\nend_header\n");
  for (int i = 0; i < 12; ++i) d.f32(static_cast<float>(i % 3 == i / 4));
  d.uint(4000000000u, 4).uint(0, 4);
  expectError(read(d.s, false), 0, "face 0 lists 4000000000 vertices; the file has 4");
  // another element with a billion records of nothing but lists, and a skipped list
  expectError(
      read("ply\nformat binary_big_endian 1.0\nelement vertex 0\nproperty float x\nproperty float "
           "y\n"
           "property float z\nelement junk 1000000000\nproperty list uint double j\nend_header\n"
           "\xff\xff\xff\xff",
           false),
      0, "the file ends inside list 'j' of junk 0 of 1000000000");
  // 10^18 records of nothing take no bytes and no time; in ASCII each is a line
  const std::string empty = "element nothing 1000000000000000000\n";
  const std::string tetra = "ply\nformat binary_little_endian 1.0\n" + empty +
                            "element vertex 0\nproperty float x\nproperty float y\n"
                            "property float z\nend_header\n";
  EXPECT_TRUE(read(tetra, false).mesh.has_value());
  expectError(read("ply\nformat ascii 1.0\n" + empty +
                       "element vertex 0\nproperty float x\n"
                       "property float y\nproperty float z\nend_header\n\n\n",
                   false),
              10, "the file ends before nothing 2 of 1000000000000000000");
  EXPECT_LT(hostile::peakKiB() - before, 16 * 1024) << "a count in a file was used to allocate";
}

// === Indices and structure

TEST(HostileStlPly, BadFacesAndHeaders) {
  const std::string head =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
      "property double z\nelement face 1\nproperty list uchar int vertex_indices\n"
      "end_header\n0 0 0\n1 0 0\n0 1 0\n";
  expectError(read(head + "3 0 1 3\n", false), 13, "vertex index 3 is out of range");
  expectError(read(head + "3 0 -1 2\n", false), 13, "vertex index -1 is out of range");
  expectError(read(head + "2 0 1\n", false), 13, "face 0 has 2 vertices");
  expectError(read(head + "256 0 1 2\n", false), 13, "expected a value of type uchar, found '256'");
  expectError(read(head + "3 0 1 2.0\n", false), 13, "expected a value of type int");
  // a short face reads as one more vertex: the vertex count on line 3 is blamed too
  expectError(read(head + "3 0 1\n", false), 3, "fewer values than its properties");
  expectError(read(head + "3 0 1 2\nextra\n", false), 14, "unexpected text after the last element");
  expectError(read("ply\nformat ascii 2.0\n", false), 2, "unsupported PLY version");
  expectError(read("ply\nelement vertex 1\n", false), 2, "expected the 'format' line");
  expectError(read("ply\nformat ascii 1.0\nproperty float x\n", false), 3,
              "a property before any element");
  expectError(read("ply\nformat ascii 1.0\nelement vertex 1\nproperty real x\n", false), 4,
              "unknown PLY type 'real'");
  expectError(read("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float "
                   "y\nend_header\n",
                   false),
              3, "element 'vertex' has no property 'z'");
  expectError(read("ply\nformat ascii 1.0\nelement vertex 1\nproperty list uchar float x\n"
                   "property float y\nproperty float z\nend_header\n",
                   false),
              4, "must be a number, not a list");
  expectError(
      read("ply\nformat ascii 1.0\nelement face 1\nproperty list float int vertex_indices\n",
           false),
      4, "a list's count type must be an integer type");
  expectError(read("ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\n", false), 4,
              "the file ends inside the PLY header");
  expectError(read("PLY\n", false), 1, "not a PLY file");
  expectError(read(std::string("ply\nformat ascii 1.0\nelement \0face 4\n", 37), false), 3,
              "an element name must be printable ASCII: '?face'");
  expectError(
      read(std::string("ply\nformat ascii 1.0\nelement face 1\nproperty int \x01\n"), false), 4,
      "a property name must be printable ASCII");
  // binary: the offset of the face record at fault
  const std::string le = plyOf(cube(), PlyEncoding::BinaryLittleEndian);
  std::string bad = le;
  const std::size_t face2 = dataStart(le) + 8 * 24 + 2 * 17;
  bad[face2 + 1 + 4 * 2] = 8;  // its third index: 8 of 8 vertices
  expectError(read(bad, false), 0,
              "byte " + std::to_string(face2) + ": face 2: vertex index 8 is out of range");
  // ASCII STL out of order
  expectError(read("solid x\nfacet normal 0 0 1\nvertex 0 0 0\n", true), 3,
              "expected 'outer loop'");
  expectError(read("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0\n", true), 4,
              "a vertex needs 3 coordinates");
  expectError(read("solid x\nendsolid x\nfacet\n", true), 3, "expected 'solid'");
  expectError(read("solid x\n", true), 1, "the file ends before 'endsolid'");
  expectError(read("solid x\nfacet normal 0 0\n", true), 2, "expected 'facet normal i j k'");
}

// === Input that cannot seek: the size is unknown and the reading streams

TEST(HostileStlPly, APipeReadsTheSame) {
  auto throughPipe = [](const std::string& bytes, bool stl) {
    int fds[2];
    EXPECT_EQ(pipe(fds), 0);
    std::thread writer([&] {
      std::size_t done = 0;
      while (done < bytes.size()) {
        const ssize_t n = write(fds[1], bytes.data() + done, bytes.size() - done);
        if (n <= 0) break;
        done += static_cast<std::size_t>(n);
      }
      close(fds[1]);
    });
    std::FILE* f = fdopen(fds[0], "rb");
    Outcome o;
    try {
      o.mesh = convexloc::parseMesh(stl ? MeshFormat::Stl : MeshFormat::Ply, f);
    } catch (const ParseError& e) {
      o.error = e.what();
    }
    writer.join();
    std::fclose(f);
    return o;
  };
  // files of several times the reader's 64 KiB buffer, in every encoding
  const MeshData sphere = meshbytes::toFloats(
      convexloc::generatePolyhedron(convexloc::PolyhedronKind::Geodesic, 5000, 1));
  const std::string stl = stlOf(sphere, false);
  for (const std::string& bytes : {stl, stlOf(sphere, true)}) {
    const Outcome whole = throughPipe(bytes, true);
    ASSERT_TRUE(whole.mesh.has_value()) << whole.error;
    const MeshData inMemory = convexloc::parseMesh(MeshFormat::Stl, bytes);
    EXPECT_EQ(whole.mesh->indices, inMemory.indices);
    EXPECT_EQ(whole.mesh->vertices, inMemory.vertices);
    EXPECT_EQ(read(bytes, true).mesh->vertices, inMemory.vertices);
  }
  for (PlyEncoding enc :
       {PlyEncoding::Ascii, PlyEncoding::BinaryLittleEndian, PlyEncoding::BinaryBigEndian}) {
    const std::string bytes = plyOf(sphere, enc, enc == PlyEncoding::BinaryBigEndian);
    const Outcome whole = throughPipe(bytes, false);
    ASSERT_TRUE(whole.mesh.has_value()) << whole.error;
    EXPECT_EQ(whole.mesh->vertices, sphere.vertices);
    EXPECT_EQ(whole.mesh->indices, sphere.indices);
    EXPECT_EQ(read(bytes, false).mesh->indices, sphere.indices);
  }
  EXPECT_EQ(throughPipe(stl.substr(0, 1000), true).error,
            "byte 1000: the file ends inside facet 18 of 5120 (its 50 bytes start at byte 984)");
  EXPECT_EQ(throughPipe(stl + "!", true).error,
            "byte " + std::to_string(stl.size()) +
                ": unexpected bytes after the last of the 5120 facets");
  const std::string ply = plyOf(cube(), PlyEncoding::BinaryBigEndian);
  EXPECT_TRUE(throughPipe(ply, false).mesh.has_value());
  EXPECT_TRUE(throughPipe(stlOf(cube(), true), true).mesh.has_value());
}

// === Garbage

TEST(HostileStlPly, RandomGarbageIsAParseError) {
  convexloc::Rng rng(20);
  for (int round = 0; round < 200; ++round) {
    std::string bytes(static_cast<std::size_t>(rng.next() % 3000), '\0');
    for (char& c : bytes) c = static_cast<char>(rng.next());
    const char* prefixes[] = {"", "solid ", "ply\n", "ply\nformat binary_little_endian 1.0\n"};
    const std::string text = prefixes[round % 4] + bytes;
    for (bool stl : {true, false}) {
      const Outcome o = read(text, stl);
      EXPECT_FALSE(o.mesh.has_value()) << "garbage accepted in round " << round;
      for (char c : o.error) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << o.error;
    }
  }
}

}  // namespace
