#include "sim/body/BodyStance.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <limits>
#include <stdexcept>

namespace figment {

namespace {

// How many clusters the points make along their widest horizontal spread, split where
// consecutive points lie more than `gap` apart (points in a plane, as 2-D).
int clusterCount(const std::vector<Eigen::Vector2d>& points, double gap) {
  if (points.empty()) return 0;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
  for (const Eigen::Vector2d& p : points) covariance += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(covariance);
  const Eigen::Vector2d axis = eigen.eigenvectors().col(1);
  std::vector<double> along;
  for (const Eigen::Vector2d& p : points) along.push_back((p - mean).dot(axis));
  std::sort(along.begin(), along.end());
  int count = 1;
  for (size_t i = 1; i < along.size(); ++i) count += along[i] - along[i - 1] > gap;
  return count;
}

// Points of `vertices` within `fraction` of the extent of the lowest (or highest) along
// `up`, in the plane perpendicular to it.
std::vector<Eigen::Vector2d> slab(const std::vector<Vec3>& vertices, const Vec3& up, double fraction, bool top) {
  double low = std::numeric_limits<double>::max(), high = -low;
  for (const Vec3& v : vertices) low = std::min(low, v.dot(up)), high = std::max(high, v.dot(up));
  const double extent = high - low;
  const Vec3 e1 = up.unitOrthogonal(), e2 = up.cross(e1);
  std::vector<Eigen::Vector2d> points;
  for (const Vec3& v : vertices) {
    const double h = v.dot(up);
    if (top ? h >= high - fraction * extent : h <= low + fraction * extent) points.emplace_back(v.dot(e1), v.dot(e2));
  }
  return points;
}

}  // namespace

std::optional<Vec3> standingUpDirection(const std::vector<Vec3>& vertices) {
  if (vertices.empty()) return std::nullopt;
  const Bounds b = boundsOf(vertices);
  const double largest = b.size().maxCoeff();
  for (int axis = 0; axis < 3; ++axis)
    for (double sign : {1.0, -1.0}) {
      if (b.size()[axis] < 0.8 * largest) continue;
      const Vec3 up = sign * Vec3::Unit(axis);
      const double gap = 0.04 * b.size()[axis];
      const bool twoFeet = clusterCount(slab(vertices, up, 0.04, false), gap) == 2;
      if (twoFeet && clusterCount(slab(vertices, up, 0.04, true), gap) == 1) return up;
    }
  return std::nullopt;
}

BodyStance measureStance(const TriangleMesh& body) {
  if (body.vertices.empty()) throw std::invalid_argument("body: no vertices");
  BodyStance stance;
  stance.up = standingUpDirection(body.vertices);
  const Vec3 along = stance.up ? Vec3(stance.up->cwiseAbs()) : Vec3(Vec3::UnitY());
  stance.stature = boundsOf(body.vertices).size().dot(along);
  return stance;
}

}  // namespace figment
