#include "sim/core/PrincipalAxes.h"

#include <Eigen/Eigenvalues>
#include <stdexcept>

namespace figment {

PrincipalAxes principalAxes(const std::vector<Vec3>& points) {
  if (points.empty()) throw std::invalid_argument("no points for principal axes");
  PrincipalAxes out;
  for (const Vec3& p : points) out.mean += p;
  out.mean /= static_cast<double>(points.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Vec3& p : points) scatter += (p - out.mean) * (p - out.mean).transpose();
  out.axes = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(scatter).eigenvectors();
  return out;
}

}  // namespace figment
