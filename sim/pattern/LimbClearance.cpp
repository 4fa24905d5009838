#include "sim/pattern/LimbClearance.h"

#include <algorithm>
#include <vector>

namespace figment {

namespace {

// Whether `p` lies inside the polygon of the panel's vertices (its outline with straight
// edges: a curved edge's bulge is a few cm at most, and the clearance covers it).
bool insideOutline(const std::vector<Vec2>& polygon, const Vec2& p) {
  bool inside = false;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Vec2 &a = polygon[i], &b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
      inside = !inside;
  }
  return inside;
}

// The offsets along the panel's normal of the body's vertices within its outline.
std::vector<double> offsetsWithin(const Panel& panel, const TriangleMesh& body) {
  std::vector<double> offsets;
  const Eigen::Matrix3d back = panel.rotation.transpose();
  for (const Vec3& v : body.vertices) {
    const Vec3 local = back * (v - panel.translation);
    if (insideOutline(panel.vertices, Vec2(local.x(), local.y()))) offsets.push_back(local.z());
  }
  return offsets;
}

}  // namespace

double clearingShift(const Panel& panel, const TriangleMesh& body, double clearance) {
  const std::vector<double> offsets = offsetsWithin(panel, body);
  if (offsets.empty()) return 0.0;
  double mean = 0.0;
  for (double z : offsets) mean += z;
  mean /= static_cast<double>(offsets.size());
  // The panel's side of the body: where its plane (offset 0) lies from their centroid.
  const double side = mean <= 0.0 ? 1.0 : -1.0;
  double beyond = 0.0;
  for (double z : offsets) beyond = std::max(beyond, side * z + clearance);
  return side * beyond;
}

void moveClearOf(Panel& panel, const TriangleMesh& body, double clearance) {
  panel.translation += clearingShift(panel, body, clearance) * (panel.rotation * Vec3::UnitZ());
}

}  // namespace figment
