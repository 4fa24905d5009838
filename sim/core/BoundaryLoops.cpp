#include "sim/core/BoundaryLoops.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <utility>

#include "sim/core/BoundaryTurning.h"

namespace figment {

std::vector<std::vector<int>> boundaryLoops(const std::vector<Triangle>& triangles) {
  std::map<std::pair<int, int>, int> use;  // by undirected edge
  for (const Triangle& t : triangles)
    for (int e = 0; e < 3; ++e) ++use[std::minmax(t[e], t[(e + 1) % 3])];
  std::multimap<int, int> next;  // boundary edges from -> to, as wound
  for (const Triangle& t : triangles)
    for (int e = 0; e < 3; ++e)
      if (use[std::minmax(t[e], t[(e + 1) % 3])] == 1) next.emplace(t[e], t[(e + 1) % 3]);
  std::vector<std::vector<int>> loops;
  while (!next.empty()) {
    std::vector<int> loop;
    const int start = next.begin()->first;
    int at = start;
    // Follow unused edges until back at the start (or stuck on a non-manifold boundary).
    for (auto edge = next.find(at); edge != next.end(); edge = next.find(at)) {
      loop.push_back(at);
      at = edge->second;
      next.erase(edge);
      if (at == start) break;
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

std::vector<double> boundaryTurningAngles(const std::vector<Vec3>& positions,
                                          const std::vector<std::vector<int>>& loops) {
  std::vector<double> angles;
  for (const std::vector<int>& loop : loops) {
    const size_t n = loop.size();
    for (size_t k = 0; k < n; ++k) {
      const Vec3 in = positions[loop[k]] - positions[loop[(k + n - 1) % n]];
      const Vec3 out = positions[loop[(k + 1) % n]] - positions[loop[k]];
      const double lengths = in.norm() * out.norm();
      const double cosine = lengths > 0.0 ? std::clamp(in.dot(out) / lengths, -1.0, 1.0) : 1.0;
      angles.push_back(std::acos(cosine) * 180.0 / M_PI);
    }
  }
  return angles;
}

double medianBoundaryTurning(const std::vector<Vec3>& positions, const std::vector<Triangle>& triangles) {
  return BoundaryTurning::median(boundaryTurningAngles(positions, boundaryLoops(triangles)));
}

TriangleMesh withBoundaryEdgesSplit(const TriangleMesh& mesh, int count) {
  std::vector<std::tuple<double, int, int>> edges;  // -length, from, to (as wound)
  for (const std::vector<int>& loop : boundaryLoops(mesh.triangles))
    for (size_t k = 0; k < loop.size(); ++k) {
      const int a = loop[k], b = loop[(k + 1) % loop.size()];
      edges.emplace_back(-(mesh.vertices[b] - mesh.vertices[a]).norm(), a, b);
    }
  std::sort(edges.begin(), edges.end());
  edges.resize(std::min(edges.size(), static_cast<size_t>(std::max(count, 0))));
  TriangleMesh out;
  out.vertices = mesh.vertices;
  std::map<std::pair<int, int>, int> middle;  // a split edge, as wound, to its new vertex
  for (const auto& [length, a, b] : edges) {
    middle[{a, b}] = static_cast<int>(out.vertices.size());
    out.vertices.push_back(0.5 * (mesh.vertices[a] + mesh.vertices[b]));
  }
  for (const Triangle& t : mesh.triangles) {
    int split = -1;
    for (int e = 0; e < 3 && split < 0; ++e)
      if (middle.count({t[e], t[(e + 1) % 3]})) split = e;
    if (split < 0) {
      out.triangles.push_back(t);
      continue;
    }
    // A triangle with two boundary edges splits along the first only: the decimation leaves
    // none (they are the spikes it refuses).
    const int a = t[split], b = t[(split + 1) % 3], c = t[(split + 2) % 3], m = middle.at({a, b});
    out.triangles.push_back({a, m, c});
    out.triangles.push_back({m, b, c});
  }
  return out;
}

void smoothLoop(std::vector<Vec3>& positions, const std::vector<int>& loop, int iterations,
                const std::function<Vec3(const Vec3&)>& onSurface) {
  // Taubin (1995): lambda = 0.5 and mu = -0.53 pass frequencies below k_PB = 1/lambda + 1/mu ~ 0.11
  // (a loop's own shape) and damp a zig-zag from vertex to vertex.
  constexpr double kLambda = 0.5, kMu = -0.53;
  const size_t n = loop.size();
  if (n < 3) return;
  std::vector<Vec3> moved(n);
  for (int i = 0; i < iterations; ++i)
    for (double factor : {kLambda, kMu}) {
      for (size_t k = 0; k < n; ++k) {
        const Vec3& x = positions[loop[k]];
        const Vec3 middle = 0.5 * (positions[loop[(k + n - 1) % n]] + positions[loop[(k + 1) % n]]);
        moved[k] = x + factor * (middle - x);
      }
      for (size_t k = 0; k < n; ++k) positions[loop[k]] = onSurface(moved[k]);
    }
}

}  // namespace figment
