#include "sim/fit/PosedSkin.h"

#include <Eigen/Dense>
#include <stdexcept>
#include <string>

namespace figment {

namespace {

// A triangle's orthonormal frame: columns along its first edge, across it in its plane,
// and its normal. Identity for a degenerate one (its offsets are then only moved).
Eigen::Matrix3d frameOf(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 u = b - a, n = u.cross(c - a);
  if (u.norm() <= 0 || n.norm() <= 0) return Eigen::Matrix3d::Identity();
  Eigen::Matrix3d frame;
  frame.col(0) = u.normalized();
  frame.col(2) = n.normalized();
  frame.col(1) = frame.col(2).cross(frame.col(0));
  return frame;
}

// Barycentric coordinates of `q` (in the plane of a, b, c), for the same point on another
// shape of the triangle; (1, 0, 0) for a degenerate one.
Vec3 barycentric(const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e0 = b - a, e1 = c - a, d = q - a;
  const double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1), d20 = d.dot(e0), d21 = d.dot(e1);
  const double denominator = d00 * d11 - d01 * d01;
  if (denominator <= 0) return Vec3(1, 0, 0);
  const double v = (d11 * d20 - d01 * d21) / denominator, w = (d00 * d21 - d01 * d20) / denominator;
  return Vec3(1 - v - w, v, w);
}

}  // namespace

// The posed skin, once it is known to be the rest skin's vertices moved: checked before
// either tree is built over it (a posed skin short of a vertex read past its end).
TriangleMesh PosedSkin::matching(const TriangleMesh& rest, TriangleMesh posed) {
  if (rest.vertices.size() != posed.vertices.size() || rest.triangles != posed.triangles)
    throw std::invalid_argument("posed skin: " + std::to_string(posed.vertices.size()) + " posed vertices and " +
                                std::to_string(posed.triangles.size()) + " triangles for " +
                                std::to_string(rest.vertices.size()) + " and " + std::to_string(rest.triangles.size()) +
                                " at rest, or other triangles");
  return posed;
}

PosedSkin::PosedSkin(TriangleMesh rest, TriangleMesh posed)
    : rest_(std::move(rest)), posed_(matching(rest_, std::move(posed))), restBvh_(rest_), posedBvh_(posed_) {}

Vec3 PosedSkin::carry(const Vec3& p, const TriangleBvh& fromBvh, const TriangleMesh& from, const TriangleMesh& to) {
  const ClosestPoint closest = fromBvh.closest(p);
  if (closest.triangle < 0) return p;
  const Triangle& t = from.triangles[closest.triangle];
  const Vec3 &a = from.vertices[t[0]], &b = from.vertices[t[1]], &c = from.vertices[t[2]];
  const Vec3 &a2 = to.vertices[t[0]], &b2 = to.vertices[t[1]], &c2 = to.vertices[t[2]];
  const Vec3 weights = barycentric(closest.point, a, b, c);
  const Vec3 there = weights.x() * a2 + weights.y() * b2 + weights.z() * c2;
  const Eigen::Matrix3d turn = frameOf(a2, b2, c2) * frameOf(a, b, c).transpose();
  return there + turn * (p - closest.point);
}

std::vector<Vec3> PosedSkin::toRest(const std::vector<Vec3>& points) const {
  std::vector<Vec3> carried;
  carried.reserve(points.size());
  for (const Vec3& p : points) carried.push_back(toRest(p));
  return carried;
}

std::vector<Vec3> PosedSkin::toPosed(const std::vector<Vec3>& points) const {
  std::vector<Vec3> carried;
  carried.reserve(points.size());
  for (const Vec3& p : points) carried.push_back(toPosed(p));
  return carried;
}

}  // namespace figment
