#include "sim/core/PlaneClip.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace figment {

double signedDistance(const CutSurface& surface, const Vec3& x) {
  return std::visit([&](const auto& s) { return s.signedDistance(x); }, surface);
}

Vec3 projected(const CutSurface& surface, const Vec3& x) {
  return std::visit([&](const auto& s) { return s.projected(x); }, surface);
}

TriangleMesh clippedByPlane(const TriangleMesh& mesh, const Plane& plane, double snap) {
  return clippedBySurfaces(mesh, {plane}, std::vector<int>(mesh.vertices.size(), 0), snap);
}

TriangleMesh clippedBySurfaces(const TriangleMesh& mesh, const std::vector<CutSurface>& surfaces,
                               const std::vector<int>& surfaceOf, double snap) {
  const std::vector<int>& planeOf = surfaceOf;
  TriangleMesh out;
  out.vertices = mesh.vertices;
  std::vector<double> d(mesh.vertices.size(), 1.0);  // signed distance to the vertex's surface
  for (size_t v = 0; v < d.size(); ++v) {
    if (planeOf[v] < 0) continue;
    d[v] = signedDistance(surfaces[planeOf[v]], mesh.vertices[v]);
    if (std::abs(d[v]) < snap) out.vertices[v] = projected(surfaces[planeOf[v]], mesh.vertices[v]), d[v] = 0.0;
  }
  std::map<std::pair<int, int>, int> cuts;  // an edge across the plane, either way round, to its cut vertex
  auto cut = [&](int a, int b) {
    const auto [it, added] = cuts.try_emplace(std::minmax(a, b), static_cast<int>(out.vertices.size()));
    if (added) {
      const double t = d[a] / (d[a] - d[b]);
      const Vec3 x = out.vertices[a] + t * (out.vertices[b] - out.vertices[a]);
      out.vertices.push_back(projected(surfaces[planeOf[a]], x));  // exactly on the surface
    }
    return it->second;
  };
  for (const Triangle& t : mesh.triangles) {
    if (planeOf[t[0]] < 0 || planeOf[t[1]] != planeOf[t[0]] || planeOf[t[2]] != planeOf[t[0]]) {
      out.triangles.push_back(t);
      continue;
    }
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
