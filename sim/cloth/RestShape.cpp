#include "sim/cloth/RestShape.h"

#include <stdexcept>
#include <string>

namespace figment {

RestShape::RestShape(const TriangleMesh& mesh)
    : triangles_(mesh.triangles), nodeCount_(mesh.vertices.size()), fromMesh_(true), mesh_(mesh) {
  corners_.reserve(triangles_.size());
  const int n = static_cast<int>(nodeCount_);
  for (const Triangle& t : triangles_) {
    std::array<Vec3, 3> c;
    // Out-of-range indices are ClothModel's to report (checkedGarment); here they rest at 0.
    for (int k = 0; k < 3; ++k) c[k] = t[k] >= 0 && t[k] < n ? mesh.vertices[t[k]] : Vec3::Zero();
    corners_.push_back(c);
  }
}

RestShape RestShape::flatPieces(std::vector<Triangle> triangles, std::vector<std::array<Vec3, 3>> corners,
                                size_t nodeCount) {
  if (triangles.size() != corners.size())
    throw std::invalid_argument("rest shape: " + std::to_string(corners.size()) + " corner triples for " +
                                std::to_string(triangles.size()) + " triangles");
  for (const Triangle& t : triangles)
    for (int i : t)
      if (i < 0 || static_cast<size_t>(i) >= nodeCount)
        throw std::invalid_argument("rest shape: node " + std::to_string(i) + " is out of range [0, " +
                                    std::to_string(nodeCount) + ")");
  RestShape shape;
  shape.triangles_ = std::move(triangles);
  shape.corners_ = std::move(corners);
  shape.nodeCount_ = nodeCount;
  return shape;
}

const Vec3& RestShape::cornerAt(int section, int node) const {
  const Triangle& t = triangles_[section];
  for (int k = 0; k < 3; ++k)
    if (t[k] == node) return corners_[section][k];
  throw std::invalid_argument("rest shape: node " + std::to_string(node) + " is not a corner of section " +
                              std::to_string(section));
}

namespace {
// Point p of a section in the frame of its edge a -> b: (along the edge, distance off it).
Eigen::Vector2d inEdgeFrame(const Vec3& a, const Vec3& b, const Vec3& p) {
  const Vec3 axis = (b - a).normalized();
  const Vec3 d = p - a;
  const double along = d.dot(axis);
  return {along, (d - along * axis).norm()};
}
}  // namespace

std::array<Vec3, 4> RestShape::hinge(int sectionA, int sectionB, const std::array<int, 4>& c) const {
  if (fromMesh_) return {mesh_.vertices[c[0]], mesh_.vertices[c[1]], mesh_.vertices[c[2]], mesh_.vertices[c[3]]};
  // Unfolded about the shared edge: A's opposite corner on one side, B's on the other, in
  // the plane z = 0, the edge as A has it. The angle there is 0 (BendingJoint::angle).
  const Vec3 &a0 = cornerAt(sectionA, c[0]), &a1 = cornerAt(sectionA, c[1]);
  const Vec3 &b0 = cornerAt(sectionB, c[0]), &b1 = cornerAt(sectionB, c[1]);
  const Eigen::Vector2d p2 = inEdgeFrame(a0, a1, cornerAt(sectionA, c[2]));
  const Eigen::Vector2d p3 = inEdgeFrame(b0, b1, cornerAt(sectionB, c[3]));
  return {Vec3::Zero(), Vec3((a1 - a0).norm(), 0.0, 0.0), Vec3(p2.x(), p2.y(), 0.0), Vec3(p3.x(), -p3.y(), 0.0)};
}

}  // namespace figment
