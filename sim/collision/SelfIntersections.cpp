// Triangle pairs that cross. Based on:
// - two triangles in general position cross iff their intersection is a segment, and each end
//   of that segment lies on an edge of one of them: so iff some edge of one passes through the
//   other (Möller, "A fast triangle-triangle intersection test", JGT 1997, names the same
//   segment; here found by six segment-triangle tests, simpler and fast enough);
// - a segment p-q passes through triangle (a, b, c) when p and q lie strictly on opposite
//   sides of its plane and the crossing point lies strictly inside all three edges;
// - candidates from the BVH's box overlaps (Ericson, Real-Time Collision Detection, ch. 6).

#include "sim/collision/SelfIntersections.h"

#include <algorithm>

#include "sim/collision/TriangleBvh.h"

namespace figment {

namespace {

bool segmentCrosses(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a);
  const double dp = n.dot(p - a), dq = n.dot(q - a);
  if (!(dp * dq < 0)) return false;  // same side, or touching the plane
  const Vec3 x = p + dp / (dp - dq) * (q - p);
  return (b - a).cross(x - a).dot(n) > 0 && (c - b).cross(x - b).dot(n) > 0 && (a - c).cross(x - c).dot(n) > 0;
}

Bounds triangleBounds(const TriangleMesh& mesh, const Triangle& t) {
  Bounds box;
  for (int k = 0; k < 3; ++k) box.extend(mesh.vertices[t[k]]);
  return box;
}

bool shareVertex(const Triangle& s, const Triangle& t) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (s[i] == t[j]) return true;
  return false;
}

}  // namespace

bool trianglesCross(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& b0, const Vec3& b1, const Vec3& b2) {
  return segmentCrosses(a0, a1, b0, b1, b2) || segmentCrosses(a1, a2, b0, b1, b2) ||
         segmentCrosses(a2, a0, b0, b1, b2) || segmentCrosses(b0, b1, a0, a1, a2) ||
         segmentCrosses(b1, b2, a0, a1, a2) || segmentCrosses(b2, b0, a0, a1, a2);
}

std::vector<TrianglePair> selfIntersections(const TriangleMesh& mesh) {
  const TriangleBvh bvh(mesh);
  std::vector<TrianglePair> pairs;
  std::vector<int> candidates;
  for (int s = 0; s < int(mesh.triangles.size()); ++s) {
    const Triangle& a = mesh.triangles[s];
    candidates.clear();
    bvh.overlapping(triangleBounds(mesh, a), candidates);
    for (const int t : candidates) {
      const Triangle& b = mesh.triangles[t];
      if (t <= s || shareVertex(a, b)) continue;
      const auto& v = mesh.vertices;
      if (trianglesCross(v[a[0]], v[a[1]], v[a[2]], v[b[0]], v[b[1]], v[b[2]])) pairs.emplace_back(s, t);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

std::vector<std::pair<int, int>> crossingLabels(const std::vector<TrianglePair>& pairs,
                                                const std::vector<int>& triangleLabel) {
  std::vector<std::pair<int, int>> labels;
  for (const auto& [s, t] : pairs) {
    const int a = triangleLabel.at(size_t(s)), b = triangleLabel.at(size_t(t));
    if (a != b) labels.emplace_back(std::min(a, b), std::max(a, b));
  }
  std::sort(labels.begin(), labels.end());
  labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
  return labels;
}

}  // namespace figment
