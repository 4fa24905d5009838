#include "sim/volumes/RadialPartShaping.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "sim/core/PrincipalAxes.h"
#include "sim/volumes/AxisSearch.h"
#include "sim/volumes/RadialDepthShaping.h"

namespace figment {

namespace {

// A radial volume on the line through `origin` along `direction`, spanning the part.
RadialDepth shapeAlong(const PartMesh& part, const std::vector<Vec3>& points, const Vec3& origin, const Vec3& direction,
                       int harmonics, double sectionSpacing) {
  double low = std::numeric_limits<double>::max(), high = -low;
  for (const Vec3& v : part.mesh.vertices) {
    const double s = (v - origin).dot(direction);
    low = std::min(low, s), high = std::max(high, s);
  }
  // A hair beyond the extreme vertices, so the caps enclose them.
  const double margin = 1e-4;
  const double length = high - low + 2 * margin;
  const int sections = std::max(2, static_cast<int>(std::ceil(length / sectionSpacing)) + 1);
  return shapeRadialDepthToPoints(points, part.mesh.vertices, origin + (low - margin) * direction, direction, length,
                                  sections, harmonics);
}

}  // namespace

double radialGapEstimate(const RadialDepth& volume, const std::vector<Vec3>& vertices) {
  double total = 0.0;
  for (const Vec3& v : vertices) {
    double s, a, rho;
    volume.toAxis(v, s, a, rho);
    const double ends = std::min(s, volume.parameters().length - s);
    total += std::max(0.0, std::min(volume.radius(s, a) - rho, ends));
  }
  return total / static_cast<double>(vertices.size());
}

RadialDepth shapeRadialPart(const PartMesh& part, int harmonics, double sectionSpacing) {
  std::vector<Vec3> points = part.mesh.vertices;
  for (const Triangle& t : part.mesh.triangles)
    points.push_back((part.mesh.vertices[t[0]] + part.mesh.vertices[t[1]] + part.mesh.vertices[t[2]]) / 3.0);
  const Vec3 bone = (part.to - part.from).normalized();
  // Candidates: the bone; the bone's direction through the part's centroid; the part's
  // principal axis nearest the bone's direction, through its centroid.
  const PrincipalAxes spread = principalAxes(points);
  const Vec3& centroid = spread.mean;
  Vec3 principal = spread.axes.col(2);
  for (int k = 0; k < 3; ++k)
    if (std::abs(spread.axes.col(k).dot(bone)) > std::abs(principal.dot(bone))) principal = spread.axes.col(k);
  if (principal.dot(bone) < 0.0) principal = -principal;
  const std::vector<std::pair<Vec3, Vec3>> axes = {{part.from, bone}, {centroid, bone}, {centroid, principal}};
  RadialDepth best = shapeAlong(part, points, axes[0].first, axes[0].second, harmonics, sectionSpacing);
  double bestGap = radialGapEstimate(best, part.mesh.vertices);
  size_t start = 0;
  for (size_t k = 1; k < axes.size(); ++k) {
    RadialDepth candidate = shapeAlong(part, points, axes[k].first, axes[k].second, harmonics, sectionSpacing);
    const double gap = radialGapEstimate(candidate, part.mesh.vertices);
    if (gap < bestGap) best = std::move(candidate), bestGap = gap, start = k;
  }
  // The genetic search from the best of them (it keeps its best: never worse).
  const AxisSearchResult searched = searchAxis({axes[start].first, axes[start].second}, [&](const Axis& axis) {
    return radialGapEstimate(shapeAlong(part, points, axis.origin, axis.direction, harmonics, sectionSpacing),
                             part.mesh.vertices);
  });
  if (searched.cost < bestGap)
    best = shapeAlong(part, points, searched.axis.origin, searched.axis.direction, harmonics, sectionSpacing);
  return best;
}

}  // namespace figment
