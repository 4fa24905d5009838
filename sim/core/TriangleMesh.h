#pragma once
// A plain indexed triangle mesh in SI units (metres): the common currency between
// the importer (io/), the simulation (sim/) and the node kit (nodes/).

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products everywhere in sim/
#include <array>
#include <limits>
#include <vector>

namespace figment {

using Vec3 = Eigen::Vector3d;
using Triangle = std::array<int, 3>;  // vertex indices, counter-clockwise seen from outside

struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<Triangle> triangles;
};

struct Bounds {
  Vec3 min = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 max = Vec3::Constant(-std::numeric_limits<double>::infinity());
  void extend(const Vec3& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  bool empty() const { return (min.array() > max.array()).any(); }
  Vec3 size() const { return max - min; }
};

Bounds boundsOf(const std::vector<Vec3>& points);

// Area-weighted vertex normals, one unit vector per vertex (+y for a vertex no triangle
// with area uses): what an exported mesh carries for smooth shading.
std::vector<Vec3> vertexNormals(const TriangleMesh& mesh);

// m^2: the sum of the triangles' areas, in triangle order.
double surfaceArea(const TriangleMesh& mesh);

// Merges vertices closer than `tolerance` (metres) and drops triangles that collapse;
// used to turn a mesh split along texture seams back into one closed surface.
TriangleMesh mergeByPosition(const TriangleMesh& mesh, double tolerance = 1e-6);

// The triangles whose centroid lies inside `box` (bounds included), in their order,
// with only the vertices they use (numbered as first used): one part of a body, say.
TriangleMesh croppedToBox(const TriangleMesh& mesh, const Bounds& box);

// The mesh with its vertices renumbered in the order the triangles first use them, the
// order an OBJ written by assimp lists them: a generated garment and its file then agree
// index for index.
TriangleMesh numberedByFirstUse(const TriangleMesh& mesh);

}  // namespace figment
