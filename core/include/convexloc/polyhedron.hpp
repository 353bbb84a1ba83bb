// convexloc — a validated convex polyhedron, and the polygon mesh it is built from.
//
// Conventions:
//   - indices are 0-based everywhere in the API (the OBJ reader converts from 1-based);
//   - a polyhedron is a closed triangle surface; every triangle is counter-clockwise seen
//     from outside, so orient3d(a, b, c, p) > 0 for p strictly inside (Shewchuk's sign);
//   - error messages name vertices and faces by their 0-based index in the input mesh,
//     print coordinates with 17 digits, and carry the source line when the mesh has one.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>
#include <vector>

#include "convexloc/geometry.hpp"

namespace convexloc {

// The most vertices, and the most triangles after fan triangulation, a polyhedron may have.
inline constexpr std::size_t kMaxPolyhedronVertices = std::size_t{1} << 27;
inline constexpr std::size_t kMaxPolyhedronFaces = std::size_t{1} << 27;

// an axis-aligned box in space; empty when lo > hi
struct Box3 {
  Vec3 lo{};
  Vec3 hi{};
};

// === Mesh data: vertices and polygon faces, as read from a file or made by a generator

// A polygon mesh before any validation: nothing here is checked.
struct MeshData {
  std::vector<Vec3> vertices;
  std::vector<std::uint32_t> faceStart{0};  // face f is indices[faceStart[f], faceStart[f + 1])
  std::vector<std::uint32_t> indices;       // vertex indices of every face, face after face
  std::vector<std::size_t> vertexLines;     // source line of each vertex, or empty
  std::vector<std::size_t> faceLines;       // source line of each face, or empty

  // number of faces
  std::size_t faceCount() const noexcept { return faceStart.size() - 1; }
  // the vertex indices of face f, in order
  std::span<const std::uint32_t> face(std::size_t f) const noexcept {
    return {indices.data() + faceStart[f], indices.data() + faceStart[f + 1]};
  }
  // appends a vertex and returns its index
  std::uint32_t addVertex(Vec3 v) {
    vertices.push_back(v);
    return static_cast<std::uint32_t>(vertices.size() - 1);
  }
  // appends a polygon face
  void addFace(std::span<const std::uint32_t> polygon) {
    indices.insert(indices.end(), polygon.begin(), polygon.end());
    faceStart.push_back(static_cast<std::uint32_t>(indices.size()));
  }
  void addFace(std::initializer_list<std::uint32_t> polygon) {
    addFace(std::span<const std::uint32_t>(polygon.begin(), polygon.size()));
  }
};

// === The polyhedron

namespace detail {
class PolyhedronBuilder;
}

// A closed convex polyhedron with positive volume, as triangles counter-clockwise from
// outside, and as plane faces: the triangles merged, exactly, where adjacent ones lie in one
// plane (a quad's two triangles, a fan-triangulated cap). Immutable once built.
class ConvexPolyhedron {
 public:
  using Triangle = std::array<std::uint32_t, 3>;

  // Validates `mesh` and normalises it, in O(F log F):
  //   - vertices with exactly equal coordinates are merged and unused vertices dropped;
  //   - a face repeating a vertex consecutively loses the repeat; a face with more than 3
  //     vertices is fan-triangulated from its first vertex (each triangle's plane is exact);
  //   - a zero-area triangle (three collinear vertices, e.g. a fan triangle at a vertex that
  //     lies on an edge of its face) is removed by flipping its longest edge with the
  //     neighbouring triangle, which leaves the surface unchanged;
  //   - a surface oriented clockwise from outside throughout is reversed (wasInverted()).
  // Throws GeometryError naming the witness: an index out of range, a non-finite coordinate,
  // a face with fewer than 3 distinct vertices or one visiting a vertex twice, a zero-area
  // triangle that cannot be flipped away, an open surface (the edge used once), a
  // non-manifold edge (used more than twice), inconsistent orientation (an edge used twice
  // in the same direction), several pieces or a surface that is not a sphere (Euler
  // characteristic), zero volume (all vertices coplanar), not convex: a reflex edge (exact
  // orient3d across every edge), two coplanar faces folded onto each other, a vertex outside
  // a face's plane, or a locally convex surface that winds around its inside more than once.
  // Coplanar neighbouring faces are valid. UsageError when the line vectors are neither
  // empty nor the size of what they annotate, or when the mesh is too large.
  explicit ConvexPolyhedron(const MeshData& mesh);

  // The exact convex hull of `points` (hull3d.cpp: randomized incremental insertion, every
  // decision an exact orient3d sign; hull_surface.cpp: the canonical form), then validated
  // as above: every point is inside or on it; the vertices are exactly the extreme points
  // (no point inside a face or an edge is one), sorted by coordinates (x, then y, then z;
  // -0 written as +0), sourceVertex() giving each one's first index in `points`; the plane
  // faces are the maximal planes, each triangulated as a fan from its smallest vertex, in
  // order of their first two vertices. The same points in any order, repeated or not, give
  // the same vertices and triangles. Throws GeometryError when
  // a coordinate is not finite, or the points are fewer than 4, all equal, collinear or
  // coplanar; UsageError for more than kMaxPolyhedronVertices points.
  static ConvexPolyhedron hullOf(std::span<const Vec3> points);

  // the vertices (merged, only those used by a face)
  std::span<const Vec3> vertices() const noexcept { return vertices_; }
  // the triangles, counter-clockwise seen from outside
  std::span<const Triangle> triangles() const noexcept { return triangles_; }
  // neighbours()[t][k]: the triangle across edge k of t, the edge from corner k to corner k + 1
  std::span<const Triangle> neighbours() const noexcept { return neighbours_; }
  // number of triangles
  std::size_t faceCount() const noexcept { return triangles_.size(); }

  // === Faces as planes: adjacent triangles in exactly one plane merged (the faces every
  // locator tests). Plane face f is numbered by its lowest triangle, so where no two
  // triangles are coplanar, plane face t is triangle t.
  // number of plane faces
  std::size_t planeCount() const noexcept { return planes_.size(); }
  // planes()[f]: three corners of plane face f, counter-clockwise seen from outside and far
  // apart (a fat triangle of the face): their plane is the face's, exactly
  std::span<const Triangle> planes() const noexcept { return planes_; }
  // planeOf()[t]: the plane face triangle t lies in
  std::span<const std::uint32_t> planeOf() const noexcept { return planeOf_; }
  // the corners of plane face f, counter-clockwise seen from outside (vertices on its edges
  // included, vertices inside it left out)
  std::span<const std::uint32_t> planeLoop(std::size_t f) const noexcept {
    return {loops_.data() + loopStart_[f], loops_.data() + loopStart_[f + 1]};
  }
  // the triangles of plane face f, in increasing order
  std::span<const std::uint32_t> planeTriangles(std::size_t f) const noexcept {
    return {planeTriangles_.data() + trianglesStart_[f],
            planeTriangles_.data() + trianglesStart_[f + 1]};
  }
  // number of vertices
  std::size_t vertexCount() const noexcept { return vertices_.size(); }
  // for each triangle, the index of the input face it comes from
  std::span<const std::uint32_t> sourceFace() const noexcept { return sourceFace_; }
  // for each vertex, its index in the input
  std::span<const std::uint32_t> sourceVertex() const noexcept { return sourceVertex_; }
  // A double point strictly inside (exactly: strictly on the inner side of every face
  // plane), when one exists; none only for polyhedra thinner than the spacing of doubles.
  std::optional<Vec3> centre() const noexcept { return centre_; }
  // the exact bounding box of the vertices
  Box3 bounds() const noexcept { return bounds_; }
  // The side of triangle t's plane p lies on: +1 inner, 0 on the plane, -1 outer. Exact.
  int side(std::size_t t, Vec3 p) const noexcept;

  // how many faces the input had
  std::size_t inputFaces() const noexcept { return inputFaces_; }
  // how many input vertices were merged into an equal one
  std::size_t mergedVertices() const noexcept { return merged_; }
  // how many input vertices no face uses
  std::size_t unusedVertices() const noexcept { return unused_; }
  // how many zero-area triangles were flipped away
  std::size_t flippedSlivers() const noexcept { return slivers_; }
  // whether the input was clockwise from outside and got reversed
  bool wasInverted() const noexcept { return inverted_; }
  // the volume and the surface area, in double precision (for display, never a decision)
  double volume() const noexcept;
  double area() const noexcept;

 private:
  friend class detail::PolyhedronBuilder;
  // `suspects`, when given, collects the faces a refusal names; `hullByConstruction` says the
  // mesh is an exact hull's, which winds once around its inside by construction
  ConvexPolyhedron(const MeshData& mesh, std::vector<std::uint32_t>* suspects,
                   bool hullByConstruction = false);

  std::vector<Vec3> vertices_;
  std::vector<Triangle> triangles_;
  std::vector<Triangle> neighbours_;
  std::vector<std::uint32_t> sourceFace_;
  std::vector<std::uint32_t> sourceVertex_;
  std::vector<Triangle> planes_;
  std::vector<std::uint32_t> planeOf_;
  std::vector<std::uint32_t> loopStart_{0}, loops_;
  std::vector<std::uint32_t> trianglesStart_{0}, planeTriangles_;
  std::optional<Vec3> centre_;
  Box3 bounds_{};
  std::size_t inputFaces_ = 0;
  std::size_t merged_ = 0;
  std::size_t unused_ = 0;
  std::size_t slivers_ = 0;
  bool inverted_ = false;
};

}  // namespace convexloc
