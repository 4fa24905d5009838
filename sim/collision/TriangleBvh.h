#pragma once
// Bounding-volume hierarchy (axis-aligned boxes, median split) over a triangle mesh,
// answering closest-point queries. Based on the standard top-down AABB tree
// (Ericson, Real-Time Collision Detection, ch. 6) and the closest point on a triangle
// by Voronoi regions (ibid. §5.1.5).

#include <vector>

#include "sim/core/TriangleMesh.h"

namespace figment {

// Which feature of a triangle the closest point lies on.
enum class TriangleFeature { Face, Edge01, Edge12, Edge20, Vertex0, Vertex1, Vertex2 };

struct ClosestPoint {
  int triangle = -1;  // -1 when nothing lies within the query radius
  Vec3 point;
  double distanceSquared = 0.0;
  TriangleFeature feature = TriangleFeature::Face;
};

// Closest point to p on triangle (a, b, c) and the feature it lies on.
ClosestPoint closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

class TriangleBvh {
 public:
  TriangleBvh() = default;
  explicit TriangleBvh(const TriangleMesh& mesh);
  // Closest point on the mesh within maxDistance of p (infinite: anywhere).
  ClosestPoint closest(const Vec3& p, double maxDistance = std::numeric_limits<double>::infinity()) const;
  // Closest point by testing every triangle: the reference the tests compare against.
  ClosestPoint closestBruteForce(const Vec3& p) const;
  // Appends to `out` every triangle (its index in the mesh) whose bounding box meets `box`
  // (touching counts), in no particular order: the candidates of an overlap test.
  void overlapping(const Bounds& box, std::vector<int>& out) const;

 private:
  struct Node {
    Bounds box;
    int left = -1, right = -1;  // children; -1 for a leaf
    int first = 0, count = 0;   // range in order_ for a leaf
  };
  int build(int first, int count);
  void testTriangle(int t, const Vec3& p, ClosestPoint& best) const;

  std::vector<Vec3> a_, b_, c_;  // triangle corners, copied for locality
  std::vector<int> order_;
  std::vector<Node> nodes_;
  std::vector<Vec3> centroids_;
};

}  // namespace figment
