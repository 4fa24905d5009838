#include "sim/progressive/RestCorrespondence.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sim/collision/TriangleBvh.h"

namespace figment {

namespace {
// Barycentric weights of p (on or beside triangle abc) in that triangle.
std::array<double, 3> barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d00 = ab.dot(ab), d01 = ab.dot(ac), d11 = ac.dot(ac), d20 = ap.dot(ab), d21 = ap.dot(ac);
  const double denominator = d00 * d11 - d01 * d01;
  if (denominator <= 0.0) return {1.0, 0.0, 0.0};  // a degenerate section: its first corner
  const double v = (d11 * d20 - d01 * d21) / denominator, w = (d00 * d21 - d01 * d20) / denominator;
  return {1.0 - v - w, v, w};
}
}  // namespace

RestCorrespondence::RestCorrespondence(const TriangleMesh& from, const TriangleMesh& onto) {
  if (onto.triangles.empty())
    throw std::invalid_argument("RestCorrespondence: the garment to map onto has no sections");
  const TriangleBvh bvh(onto);
  for (const Vec3& p : from.vertices) {
    const ClosestPoint closest = bvh.closest(p);
    const Triangle& t = onto.triangles[closest.triangle];
    corners_.push_back(t);
    weights_.push_back(barycentric(closest.point, onto.vertices[t[0]], onto.vertices[t[1]], onto.vertices[t[2]]));
    largestGap_ = std::max(largestGap_, std::sqrt(closest.distanceSquared));
  }
}

std::vector<Vec3> RestCorrespondence::carry(const std::vector<Vec3>& ontoDraped) const {
  std::vector<Vec3> out;
  out.reserve(corners_.size());
  for (size_t i = 0; i < corners_.size(); ++i) {
    const Triangle& t = corners_[i];
    const std::array<double, 3>& w = weights_[i];
    out.push_back(w[0] * ontoDraped[t[0]] + w[1] * ontoDraped[t[1]] + w[2] * ontoDraped[t[2]]);
  }
  return out;
}

}  // namespace figment
