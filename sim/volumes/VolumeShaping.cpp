#include "sim/volumes/VolumeShaping.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "sim/volumes/CapsuleShaping.h"
#include "sim/volumes/RadialPartShaping.h"

namespace figment {

namespace {

constexpr double kSplitGap = 0.008;  // m: a capsule with a larger mean gap is split
constexpr int kMaxCapsules = 6;      // per part: 4 left the torso parts at 17-21 mm (median 10.9)

double meanGap(const Capsule& capsule, const std::vector<Vec3>& points) {
  double total = 0.0;
  for (const Vec3& p : points) total += std::abs(capsule.nearestFast(p).distance);
  return total / static_cast<double>(points.size());
}

CapsuleParameters shapeEnclosing(const std::vector<Vec3>& points, uint64_t seed) {
  std::vector<Vec3> sample;
  const size_t every = std::max<size_t>(1, (points.size() + 299) / 300);
  for (size_t i = 0; i < points.size(); i += every) sample.push_back(points[i]);
  CapsuleShapingOptions options;
  options.seed = static_cast<uint32_t>(seed);
  options.generations = 300;
  options.enclose = false;
  CapsuleParameters c = shapeCapsule(sample, options).parameters;
  growToEnclose(c, points);
  return c;
}

// Capsules for `points`, split along the capsule's axis while that helps; appends them
// and returns the summed gap over the points.
double shapePieces(const std::vector<Vec3>& points, uint64_t seed, int budget, std::vector<CapsuleParameters>& out) {
  const CapsuleParameters whole = shapeEnclosing(points, seed);
  const Capsule capsule(whole);
  const double gap = meanGap(capsule, points);
  if (gap <= kSplitGap || budget < 2 || points.size() < 40) {
    out.push_back(whole);
    return gap * static_cast<double>(points.size());
  }
  std::vector<double> along(points.size());
  for (size_t i = 0; i < points.size(); ++i) along[i] = capsule.toUnit(points[i]).y();
  std::vector<double> sorted = along;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double cut = sorted[sorted.size() / 2];
  std::vector<Vec3> low, high;
  for (size_t i = 0; i < points.size(); ++i) (along[i] < cut ? low : high).push_back(points[i]);
  if (low.size() < 8 || high.size() < 8) {
    out.push_back(whole);
    return gap * static_cast<double>(points.size());
  }
  std::vector<CapsuleParameters> pieces;
  const int lowBudget = budget / 2;
  const double split =
      shapePieces(low, seed + 1, lowBudget, pieces) + shapePieces(high, seed + 2, budget - lowBudget, pieces);
  if (split < gap * static_cast<double>(points.size())) {
    out.insert(out.end(), pieces.begin(), pieces.end());
    return split;
  }
  out.push_back(whole);
  return gap * static_cast<double>(points.size());
}

}  // namespace

double signedDistance(const CollisionVolumeParameters& volume, const Vec3& p) {
  return volume.kind == CollisionVolumeParameters::Kind::Capsule ? Capsule(volume.capsule).nearest(p).distance
                                                                 : RadialDepth(volume.radial).nearest(p).distance;
}

std::vector<CollisionVolumeParameters> shapePartCapsules(const PartMesh& part, const VolumeShapingOptions& options) {
  std::vector<CapsuleParameters> capsules;
  shapePieces(part.mesh.vertices, options.seed, kMaxCapsules, capsules);
  std::vector<CollisionVolumeParameters> out;
  for (const CapsuleParameters& c : capsules)
    out.push_back({part.name, CollisionVolumeParameters::Kind::Capsule, c, {}});
  return out;
}

std::vector<CollisionVolumeParameters> shapePartRadial(const PartMesh& part, const VolumeShapingOptions& options) {
  const RadialDepth radial = shapeRadialPart(part, options.harmonics, options.sectionSpacing);
  const std::vector<CollisionVolumeParameters> suited = {
      {part.name, CollisionVolumeParameters::Kind::Radial, {}, radial.parameters()}};
  double radialGap = 0.0;
  for (const Vec3& v : part.mesh.vertices) radialGap += std::abs(radial.nearest(v).distance);
  if (radialGap <= kSplitGap * static_cast<double>(part.mesh.vertices.size())) return suited;
  const std::vector<CollisionVolumeParameters> capsules = shapePartCapsules(part, options);
  // The capsules' gap by the same estimate as the radial one's: each vertex's depth in
  // the deepest capsule holding it.
  double capsuleGap = 0.0;
  for (const Vec3& v : part.mesh.vertices) {
    double deepest = 0.0;
    for (const CollisionVolumeParameters& c : capsules) deepest = std::max(deepest, -signedDistance(c, v));
    capsuleGap += deepest;
  }
  return capsuleGap < radialGap ? capsules : suited;
}

namespace {

// `shapePart` on every part of `body` with enough vertices to fit, in the skeleton's order,
// saying which to `progress`.
template <typename ShapePart>
std::vector<CollisionVolumeParameters> shapeEachPart(const TriangleMesh& body, const Skeleton& skeleton,
                                                     const VolumeShapingOptions& options, ShapePart shapePart) {
  std::vector<PartMesh> parts = splitIntoParts(body, skeleton);
  std::erase_if(parts, [](const PartMesh& part) { return part.mesh.vertices.size() < 4; });
  std::vector<CollisionVolumeParameters> out;
  for (size_t i = 0; i < parts.size(); ++i) {
    if (options.progress) options.progress(parts[i].name, static_cast<int>(i), static_cast<int>(parts.size()));
    const std::vector<CollisionVolumeParameters> v = shapePart(parts[i]);
    out.insert(out.end(), v.begin(), v.end());
  }
  return out;
}

}  // namespace

std::vector<CollisionVolumeParameters> shapeCapsules(const TriangleMesh& body, const Skeleton& skeleton,
                                                     const VolumeShapingOptions& options) {
  return shapeEachPart(body, skeleton, options, [&](const PartMesh& part) { return shapePartCapsules(part, options); });
}

std::vector<CollisionVolumeParameters> shapeRadialVolumes(const TriangleMesh& body, const Skeleton& skeleton,
                                                          const VolumeShapingOptions& options) {
  return shapeEachPart(body, skeleton, options, [&](const PartMesh& part) { return shapePartRadial(part, options); });
}

}  // namespace figment
