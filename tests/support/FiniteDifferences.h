#pragma once
// Central finite differences, the reference that analytic gradients and forces are
// checked against.

#include "sim/core/TriangleMesh.h"

#include <functional>
#include <vector>

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

}  // namespace figment::meshes
