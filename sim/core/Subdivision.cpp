#include "sim/core/Subdivision.h"

#include <algorithm>
#include <map>
#include <utility>

namespace figment {

TriangleMesh subdivided(const TriangleMesh& mesh) {
  TriangleMesh out;
  out.vertices = mesh.vertices;
  out.triangles.reserve(4 * mesh.triangles.size());
  std::map<std::pair<int, int>, int> midpoints;  // an edge, either way round, to its new vertex
  auto midpoint = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    const auto [it, added] = midpoints.try_emplace({key.first, key.second}, static_cast<int>(out.vertices.size()));
    if (added) out.vertices.push_back(0.5 * (mesh.vertices[a] + mesh.vertices[b]));
    return it->second;
  };
  for (const Triangle& t : mesh.triangles) {
    const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
    out.triangles.push_back({t[0], ab, ca});
    out.triangles.push_back({ab, t[1], bc});
    out.triangles.push_back({ca, bc, t[2]});
    out.triangles.push_back({ab, bc, ca});
  }
  return out;
}

}  // namespace figment
