#include "TriangleMesh.h"

#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace figment {

Bounds boundsOf(const std::vector<Vec3>& points) {
  Bounds bounds;
  for (const Vec3& p : points) bounds.extend(p);
  return bounds;
}

TriangleMesh mergeByPosition(const TriangleMesh& mesh, double tolerance) {
  // Snap to a grid of cell `tolerance` and look in the 27 neighbouring cells, so two
  // vertices closer than the tolerance meet even across a cell border. The first
  // occurrence keeps its place: the order is deterministic.
  struct CellHash {
    size_t operator()(const std::array<int64_t, 3>& c) const {
      return std::hash<int64_t>()(c[0] * 73856093 ^ c[1] * 19349663 ^ c[2] * 83492791);
    }
  };
  const double cell = tolerance > 0.0 ? tolerance : 1e-12;
  auto cellOf = [&](const Vec3& p) {
    return std::array<int64_t, 3>{static_cast<int64_t>(std::floor(p.x() / cell)),
                                  static_cast<int64_t>(std::floor(p.y() / cell)),
                                  static_cast<int64_t>(std::floor(p.z() / cell))};
  };
  std::unordered_map<std::array<int64_t, 3>, std::vector<int>, CellHash> grid;
  TriangleMesh merged;
  std::vector<int> remap(mesh.vertices.size());
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec3& p = mesh.vertices[i];
    const auto c = cellOf(p);
    int found = -1;
    for (int dx = -1; dx <= 1 && found < 0; ++dx)
      for (int dy = -1; dy <= 1 && found < 0; ++dy)
        for (int dz = -1; dz <= 1 && found < 0; ++dz) {
          const auto it = grid.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == grid.end()) continue;
          for (int candidate : it->second)
            if ((merged.vertices[candidate] - p).norm() <= tolerance) {
              found = candidate;
              break;
            }
        }
    if (found < 0) {
      found = static_cast<int>(merged.vertices.size());
      merged.vertices.push_back(p);
      grid[c].push_back(found);
    }
    remap[i] = found;
  }
  for (const Triangle& t : mesh.triangles) {
    const Triangle r{remap[t[0]], remap[t[1]], remap[t[2]]};
    if (r[0] != r[1] && r[1] != r[2] && r[2] != r[0]) merged.triangles.push_back(r);
  }
  return merged;
}

}  // namespace figment
