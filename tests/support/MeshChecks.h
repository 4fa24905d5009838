#pragma once
// Topology checks on triangle meshes, shared by the tests of generated and imported meshes.

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>
#include <vector>

#include "sim/core/TriangleMesh.h"

namespace figment::checks {

// How many triangles use each undirected edge (smaller index first).
inline std::map<std::pair<int, int>, int> edgeUses(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> uses;
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++uses[std::minmax(t[k], t[(k + 1) % 3])];
  return uses;
}

inline int mostTrianglesOnAnEdge(const TriangleMesh& mesh) {
  int most = 0;
  for (const auto& [edge, count] : edgeUses(mesh)) most = std::max(most, count);
  return most;
}

inline bool everyEdgeSharedByTwo(const TriangleMesh& mesh) {
  const auto uses = edgeUses(mesh);
  return std::all_of(uses.begin(), uses.end(), [](const auto& use) { return use.second == 2; });
}

// Consistently oriented: no directed edge is walked twice, so the two triangles on an interior
// edge walk it in opposite directions.
inline bool consistentlyOriented(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> directed;
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      if (++directed[{t[k], t[(k + 1) % 3]}] > 1) return false;
  return true;
}

// Connected components of the triangles (through shared vertices), by union-find.
inline int connectedComponents(const TriangleMesh& mesh) {
  std::vector<int> parent(mesh.vertices.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const Triangle& t : mesh.triangles) {
    parent[root(t[1])] = root(t[0]);
    parent[root(t[2])] = root(t[0]);
  }
  std::vector<char> used(mesh.vertices.size(), 0);
  for (const Triangle& t : mesh.triangles)
    for (int v : t) used[v] = 1;
  int components = 0;
  for (size_t v = 0; v < parent.size(); ++v)
    if (used[v] && root(static_cast<int>(v)) == static_cast<int>(v)) ++components;
  return components;
}

// Volume enclosed by a closed mesh, positive when it is wound counter-clockwise from outside:
// V = 1/6 sum a . (b x c) over its triangles.
inline double signedVolume(const TriangleMesh& mesh) {
  double volume = 0;
  for (const Triangle& t : mesh.triangles)
    volume += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]]));
  return volume / 6.0;
}

inline Vec3 normalOf(const TriangleMesh& mesh, const Triangle& t) {
  return (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
}

inline Vec3 centroidOf(const TriangleMesh& mesh, const Triangle& t) {
  return (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0;
}

// Ray parity: a point is inside a closed surface when a ray from it crosses the surface an
// odd number of times (Moeller-Trumbore ray/triangle test; a skew direction misses edges).
inline bool insideClosedSurface(const TriangleMesh& surface, const Vec3& p) {
  const Vec3 direction = Vec3(0.1234, 0.9876, 0.0567).normalized();
  int crossings = 0;
  for (const Triangle& t : surface.triangles) {
    const Vec3 &a = surface.vertices[t[0]], &b = surface.vertices[t[1]], &c = surface.vertices[t[2]];
    const Vec3 e1 = b - a, e2 = c - a, q = direction.cross(e2);
    const double det = e1.dot(q);
    if (std::abs(det) < 1e-15) continue;
    const Vec3 s = p - a;
    const double u = s.dot(q) / det;
    if (u < 0 || u > 1) continue;
    const Vec3 r = s.cross(e1);
    const double v = direction.dot(r) / det;
    if (v < 0 || u + v > 1) continue;
    if (e2.dot(r) / det > 0) ++crossings;
  }
  return crossings % 2 == 1;
}

}  // namespace figment::checks
