#include "sim/collision/TriangleBvh.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace figment {

ClosestPoint closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  // Voronoi-region walk (Ericson §5.1.5): vertex regions, then edge regions, then the face.
  ClosestPoint result;
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  auto done = [&](const Vec3& q, TriangleFeature feature) {
    result.point = q;
    result.feature = feature;
    result.distanceSquared = (p - q).squaredNorm();
    return result;
  };
  if (d1 <= 0.0 && d2 <= 0.0) return done(a, TriangleFeature::Vertex0);
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return done(b, TriangleFeature::Vertex1);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return done(a + ab * (d1 / (d1 - d3)), TriangleFeature::Edge01);
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return done(c, TriangleFeature::Vertex2);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return done(a + ac * (d2 / (d2 - d6)), TriangleFeature::Edge20);
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
    return done(b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))), TriangleFeature::Edge12);
  const double denominator = 1.0 / (va + vb + vc);
  return done(a + ab * (vb * denominator) + ac * (vc * denominator), TriangleFeature::Face);
}

namespace {
constexpr int kLeafSize = 4;

bool boxesMeet(const Bounds& a, const Bounds& b) {
  return (a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all();
}

double squaredDistanceToBox(const Vec3& p, const Bounds& box) {
  const Vec3 below = (box.min - p).cwiseMax(0.0);
  const Vec3 above = (p - box.max).cwiseMax(0.0);
  return (below + above).squaredNorm();
}
}  // namespace

// Throws std::invalid_argument naming the first triangle that names a vertex the mesh lacks
// (never reading past the vertices).
TriangleBvh::TriangleBvh(const TriangleMesh& mesh) {
  const size_t n = mesh.triangles.size();
  a_.resize(n);
  b_.resize(n);
  c_.resize(n);
  centroids_.resize(n);
  const size_t vertices = mesh.vertices.size();
  for (size_t t = 0; t < n; ++t) {
    const Triangle& tri = mesh.triangles[t];
    for (int corner : tri)
      if (corner < 0 || static_cast<size_t>(corner) >= vertices)
        throw std::invalid_argument("triangle " + std::to_string(t) + " names vertex " + std::to_string(corner) +
                                    " of a mesh of " + std::to_string(vertices));
    a_[t] = mesh.vertices[tri[0]];
    b_[t] = mesh.vertices[tri[1]];
    c_[t] = mesh.vertices[tri[2]];
    centroids_[t] = (a_[t] + b_[t] + c_[t]) / 3.0;
  }
  order_.resize(n);
  std::iota(order_.begin(), order_.end(), 0);
  nodes_.reserve(2 * n / kLeafSize + 1);
  if (n > 0) build(0, static_cast<int>(n));
}

int TriangleBvh::build(int first, int count) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Bounds box, centres;
  for (int i = first; i < first + count; ++i) {
    const int t = order_[i];
    box.extend(a_[t]);
    box.extend(b_[t]);
    box.extend(c_[t]);
    centres.extend(centroids_[t]);
  }
  nodes_[index].box = box;
  if (count <= kLeafSize) {
    nodes_[index].first = first;
    nodes_[index].count = count;
    return index;
  }
  // Median split along the widest extent of the triangle centres: balanced, deterministic.
  int axis = 0;
  centres.size().maxCoeff(&axis);
  const int half = count / 2;
  std::nth_element(
      order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count, [&](int l, int r) {
        return centroids_[l][axis] < centroids_[r][axis] || (centroids_[l][axis] == centroids_[r][axis] && l < r);
      });
  const int left = build(first, half);
  const int right = build(first + half, count - half);
  nodes_[index].left = left;
  nodes_[index].right = right;
  return index;
}

void TriangleBvh::testTriangle(int t, const Vec3& p, ClosestPoint& best) const {
  ClosestPoint candidate = closestPointOnTriangle(p, a_[t], b_[t], c_[t]);
  if (candidate.distanceSquared < best.distanceSquared ||
      (candidate.distanceSquared == best.distanceSquared && best.triangle >= 0 && t < best.triangle)) {
    candidate.triangle = t;
    best = candidate;
  }
}

ClosestPoint TriangleBvh::closest(const Vec3& p, double maxDistance) const {
  ClosestPoint best;
  best.distanceSquared = maxDistance * maxDistance;
  if (nodes_.empty()) return best;
  // Depth-first, nearer child first, pruning boxes farther than the best so far.
  int stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (squaredDistanceToBox(p, node.box) > best.distanceSquared) continue;
    if (node.left < 0) {
      for (int i = node.first; i < node.first + node.count; ++i) testTriangle(order_[i], p, best);
      continue;
    }
    const double dl = squaredDistanceToBox(p, nodes_[node.left].box);
    const double dr = squaredDistanceToBox(p, nodes_[node.right].box);
    if (dl < dr) {
      stack[top++] = node.right;
      stack[top++] = node.left;
    } else {
      stack[top++] = node.left;
      stack[top++] = node.right;
    }
  }
  return best;
}

void TriangleBvh::overlapping(const Bounds& box, std::vector<int>& out) const {
  if (nodes_.empty()) return;
  int stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!boxesMeet(node.box, box)) continue;
    if (node.left >= 0) {
      stack[top++] = node.left;
      stack[top++] = node.right;
      continue;
    }
    for (int i = node.first; i < node.first + node.count; ++i) {
      const int t = order_[i];
      Bounds own;
      own.extend(a_[t]);
      own.extend(b_[t]);
      own.extend(c_[t]);
      if (boxesMeet(own, box)) out.push_back(t);
    }
  }
}

ClosestPoint TriangleBvh::closestBruteForce(const Vec3& p) const {
  ClosestPoint best;
  best.distanceSquared = std::numeric_limits<double>::infinity();
  for (int t = 0; t < static_cast<int>(a_.size()); ++t) testTriangle(t, p, best);
  return best;
}

}  // namespace figment
