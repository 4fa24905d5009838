#include "sim/core/PlaneClip.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace figment {

TriangleMesh clippedByPlane(const TriangleMesh& mesh, const Plane& plane, double snap) {
  TriangleMesh out;
  out.vertices = mesh.vertices;
  std::vector<double> d(mesh.vertices.size());
  for (size_t v = 0; v < d.size(); ++v) {
    d[v] = plane.signedDistance(mesh.vertices[v]);
    if (std::abs(d[v]) < snap) out.vertices[v] -= d[v] * plane.normal, d[v] = 0.0;
  }
  std::map<std::pair<int, int>, int> cuts;  // an edge across the plane, either way round, to its cut vertex
  auto cut = [&](int a, int b) {
    const auto [it, added] = cuts.try_emplace(std::minmax(a, b), static_cast<int>(out.vertices.size()));
    if (added) {
      const double t = d[a] / (d[a] - d[b]);
      Vec3 x = out.vertices[a] + t * (out.vertices[b] - out.vertices[a]);
      out.vertices.push_back(x - plane.signedDistance(x) * plane.normal);  // exactly on the plane
    }
    return it->second;
  };
  for (const Triangle& t : mesh.triangles) {
    // The kept polygon: the corners in front (or on the plane) and the cuts between.
    std::vector<int> polygon;
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if (d[a] >= 0.0) polygon.push_back(a);
      if ((d[a] > 0.0 && d[b] < 0.0) || (d[a] < 0.0 && d[b] > 0.0)) polygon.push_back(cut(a, b));
    }
    const bool anyInFront = d[t[0]] > 0.0 || d[t[1]] > 0.0 || d[t[2]] > 0.0;
    if (!anyInFront) continue;  // behind, or lying in the plane
    for (size_t k = 1; k + 1 < polygon.size(); ++k) out.triangles.push_back({polygon[0], polygon[k], polygon[k + 1]});
  }
  return numberedByFirstUse(out);
}

}  // namespace figment
