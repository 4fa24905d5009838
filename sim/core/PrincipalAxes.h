#pragma once
// The mean of a point set and its principal axes (eigenvectors of the scatter matrix),
// for fits that start from a part's shape.

#include <vector>

#include "sim/core/TriangleMesh.h"

namespace figment {

struct PrincipalAxes {
  Vec3 mean = Vec3::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  // columns, unit, by increasing spread
};

// Throws std::invalid_argument when `points` is empty.
PrincipalAxes principalAxes(const std::vector<Vec3>& points);

}  // namespace figment
