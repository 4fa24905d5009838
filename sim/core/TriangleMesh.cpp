// Welding by position with a uniform grid (spatial hashing, as in Teschner et al. 2003,
// "Optimized Spatial Hashing for Collision Detection of Deformable Objects": the hash
// of a cell is the xor of its integer coordinates times three large primes).

#include "sim/core/TriangleMesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "sim/core/ParameterChecks.h"

namespace figment {

namespace {

using Cell = std::array<int64_t, 3>;

struct CellHash {
  size_t operator()(const Cell& c) const {
    // Unsigned arithmetic: wrapping is defined, a signed overflow would not be.
    const uint64_t h = static_cast<uint64_t>(c[0]) * 73856093u ^ static_cast<uint64_t>(c[1]) * 19349663u ^
                       static_cast<uint64_t>(c[2]) * 83492791u;
    return static_cast<size_t>(h);
  }
};

// Any cell at least as large as the tolerance finds every partner in the 27 cells around
// a point; a floor on the size keeps integer cell coordinates in range for tiny tolerances.
constexpr double kSmallestCell = 1e-9;  // m

}  // namespace

std::vector<Vec3> vertexNormals(const TriangleMesh& mesh) {
  std::vector<Vec3> normals(mesh.vertices.size(), Vec3::Zero());
  for (const Triangle& t : mesh.triangles) {
    // The cross product's length is twice the triangle's area: the weight.
    const Vec3 n = (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
    for (const int corner : t) normals[corner] += n;
  }
  for (Vec3& n : normals) n = n.norm() > 0.0 ? Vec3(n.normalized()) : Vec3(0, 1, 0);
  return normals;
}

double surfaceArea(const TriangleMesh& mesh) {
  double sum = 0.0;
  for (const Triangle& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    sum += 0.5 * (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).norm();
  }
  return sum;
}

Bounds boundsOf(const std::vector<Vec3>& points) {
  Bounds bounds;
  for (const Vec3& p : points) bounds.extend(p);
  return bounds;
}

TriangleMesh mergeByPosition(const TriangleMesh& mesh, double tolerance) {
  requireNonNegative("tolerance", tolerance);
  const double cell = std::max(tolerance, kSmallestCell);
  // A coordinate far beyond any body (or not finite) goes to the outermost cell: casting a double
  // outside int64's range is undefined behaviour (UBSan, tests/fuzz/fuzz_mesh: a vertex at
  // -1.1e20). Merging still compares true distances, so sharing a cell only costs a comparison.
  auto index = [cell](double v) {
    constexpr double kLimit = 4.0e18;  // below 2^62: a neighbour's index (+-1) stays in range
    const double k = std::floor(v / cell);
    return static_cast<int64_t>(std::isnan(k) ? 0.0 : std::clamp(k, -kLimit, kLimit));
  };
  auto cellOf = [index](const Vec3& p) { return Cell{index(p.x()), index(p.y()), index(p.z())}; };

  // Each vertex joins the earliest kept vertex within the tolerance, or is kept itself:
  // kept vertices stay in the order of their first occurrence, whatever the hash does.
  std::unordered_map<Cell, std::vector<int>, CellHash> grid;
  TriangleMesh merged;
  std::vector<int> remap(mesh.vertices.size());
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec3& p = mesh.vertices[i];
    const Cell c = cellOf(p);
    int found = -1;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = grid.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == grid.end()) continue;
          for (const int candidate : it->second)
            if ((found < 0 || candidate < found) && (merged.vertices[candidate] - p).norm() <= tolerance)
              found = candidate;
        }
    if (found < 0) {
      found = static_cast<int>(merged.vertices.size());
      merged.vertices.push_back(p);
      grid[c].push_back(found);
    }
    remap[i] = found;
  }

  // A triangle whose corners met has no area left: drop it.
  for (const Triangle& t : mesh.triangles) {
    const Triangle r{remap[t[0]], remap[t[1]], remap[t[2]]};
    if (r[0] != r[1] && r[1] != r[2] && r[2] != r[0]) merged.triangles.push_back(r);
  }
  return merged;
}

TriangleMesh croppedToBox(const TriangleMesh& mesh, const Bounds& box) {
  TriangleMesh part;
  std::vector<int> remap(mesh.vertices.size(), -1);
  for (const Triangle& t : mesh.triangles) {
    const Vec3 centroid = (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0;
    if ((centroid.array() < box.min.array()).any() || (centroid.array() > box.max.array()).any()) continue;
    Triangle kept;
    for (int k = 0; k < 3; ++k) {
      int& index = remap[t[k]];
      if (index < 0) {
        index = static_cast<int>(part.vertices.size());
        part.vertices.push_back(mesh.vertices[t[k]]);
      }
      kept[k] = index;
    }
    part.triangles.push_back(kept);
  }
  return part;
}

TriangleMesh numberedByFirstUse(const TriangleMesh& mesh) {
  std::vector<int> renumbered(mesh.vertices.size(), -1);
  TriangleMesh out;
  for (const Triangle& t : mesh.triangles) {
    Triangle r{};
    for (int k = 0; k < 3; ++k) {
      if (renumbered[t[k]] < 0) {
        renumbered[t[k]] = static_cast<int>(out.vertices.size());
        out.vertices.push_back(mesh.vertices[t[k]]);
      }
      r[k] = renumbered[t[k]];
    }
    out.triangles.push_back(r);
  }
  return out;
}

}  // namespace figment
