#include "sim/progressive/SplitPlacement.h"

#include <Eigen/LU>
#include <algorithm>

namespace figment {

namespace {
Vec3 faceNormal(const Triangle& t, const auto& position) {
  return (position(t[1]) - position(t[0])).cross(position(t[2]) - position(t[0]));
}
}  // namespace

void placeSplit(const VertexSplit& split, const MeshLevel& level, std::vector<Vec3>& x, std::vector<Vec3>& v) {
  const int k = split.kept;
  const Vec3& restK = level.rest(k);
  Eigen::Matrix3d deformedRest = Eigen::Matrix3d::Zero(), restRest = Eigen::Matrix3d::Zero();
  Vec3 restNormal = Vec3::Zero(), deformedNormal = Vec3::Zero(), velocity = v[k];
  std::vector<int> ring;
  double lengths = 0.0;
  for (int f : level.facesOf(k)) {
    const Triangle& t = level.corners(f);
    restNormal += faceNormal(t, [&](int i) { return level.rest(i); });
    deformedNormal += faceNormal(t, [&](int i) { return x[i]; });
    for (int n : t)
      if (n != k && std::find(ring.begin(), ring.end(), n) == ring.end()) ring.push_back(n);
  }
  for (int n : ring) {
    const Vec3 dX = level.rest(n) - restK, dx = x[n] - x[k];
    deformedRest += dx * dX.transpose();
    restRest += dX * dX.transpose();
    lengths += dX.norm();
    velocity += v[n];
  }
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  if (!ring.empty() && restNormal.norm() > 0.0 && deformedNormal.norm() > 0.0) {
    // The normal, scaled to the ring's mean edge, stands for the direction across.
    const double h = lengths / ring.size();
    const Vec3 N = h * restNormal.normalized(), n = h * deformedNormal.normalized();
    const Eigen::Matrix3d A = restRest + N * N.transpose();
    if (std::abs(A.determinant()) > 1e-30) F = (deformedRest + n * N.transpose()) * A.inverse();
  }
  velocity /= static_cast<double>(ring.size() + 1);
  const Vec3 xk = x[k];
  x[split.added] = xk + F * (split.addedRest - restK);
  x[k] = xk + F * (split.keptRest - restK);
  v[split.added] = v[k] = velocity;
}

}  // namespace figment
