#pragma once
// Central finite differences, the reference that analytic gradients and forces are
// checked against.

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "sim/core/TriangleMesh.h"

namespace figment::meshes {

// d f / d x_i for every point and axis, by central differences of step h.
inline std::vector<Vec3> numericalGradient(const std::function<double(const std::vector<Vec3>&)>& f,
                                           const std::vector<Vec3>& x, double h) {
  std::vector<Vec3> gradient(x.size(), Vec3::Zero());
  for (size_t i = 0; i < x.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      auto plus = x, minus = x;
      plus[i][k] += h;
      minus[i][k] -= h;
      gradient[i][k] = (f(plus) - f(minus)) / (2 * h);
    }
  return gradient;
}

// d f_i / d x_j for a function of points to points (3 m x 3 n, row 3 i + k: component k
// of f_i), by central differences of step h.
inline Eigen::MatrixXd numericalJacobian(const std::function<std::vector<Vec3>(const std::vector<Vec3>&)>& f,
                                         const std::vector<Vec3>& x, double h) {
  Eigen::MatrixXd jacobian;
  for (size_t j = 0; j < x.size(); ++j)
    for (int k = 0; k < 3; ++k) {
      auto plus = x, minus = x;
      plus[j][k] += h;
      minus[j][k] -= h;
      const std::vector<Vec3> up = f(plus), down = f(minus);
      if (jacobian.size() == 0) jacobian = Eigen::MatrixXd::Zero(3 * up.size(), 3 * x.size());
      for (size_t i = 0; i < up.size(); ++i) jacobian.block<3, 1>(3 * i, 3 * j + k) = (up[i] - down[i]) / (2 * h);
    }
  return jacobian;
}

}  // namespace figment::meshes
