#include "sim/body/Skinning.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "sim/body/Posing.h"
#include "sim/core/ParameterChecks.h"

namespace figment {

namespace {
double smoothstep(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

double squaredDistanceToBone(const Skeleton& skeleton, const BodyPart& part, const Vec3& p) {
  const Vec3& a = skeleton.joints[part.from].position;
  const Vec3 ab = skeleton.joints[part.to].position - a;
  const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-18), 0.0, 1.0);
  return (p - (a + t * ab)).squaredNorm();
}

// Of the parts starting at joint `j` (other than `self`), the nearest to p; -1 for none.
int partStartingAt(const Skeleton& skeleton, int j, int self, const Vec3& p) {
  int best = -1;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < skeleton.parts.size(); ++k) {
    if (skeleton.parts[k].from != j || static_cast<int>(k) == self) continue;
    const double d = squaredDistanceToBone(skeleton, skeleton.parts[k], p);
    if (d < bestDistance) best = static_cast<int>(k), bestDistance = d;
  }
  return best;
}
}  // namespace

SkinWeights skinWeights(const Skeleton& skeleton, const std::vector<Vec3>& restVertices, double blendRadius) {
  return skinWeights(skeleton, restVertices, std::vector<int>(restVertices.size(), -1), blendRadius);
}

SkinWeights skinWeights(const Skeleton& skeleton, const std::vector<Vec3>& restVertices, const std::vector<int>& given,
                        double blendRadius) {
  requirePositive("blendRadius", blendRadius);
  if (skeleton.parts.empty() && !restVertices.empty())
    throw std::invalid_argument("skeleton has no parts to skin " + std::to_string(restVertices.size()) +
                                " vertices to");
  if (given.size() != restVertices.size())
    throw std::invalid_argument("owner: " + std::to_string(given.size()) + " parts for " +
                                std::to_string(restVertices.size()) + " vertices");
  std::vector<int> owner = given;
  for (size_t v = 0; v < owner.size(); ++v)
    if (owner[v] >= static_cast<int>(skeleton.parts.size()))
      throw std::invalid_argument("owner[" + std::to_string(v) + "] = " + std::to_string(owner[v]) + " is not a part");
  if (std::find(owner.begin(), owner.end(), -1) != owner.end()) {
    const std::vector<int> nearest = assignParts(skeleton, restVertices);
    for (size_t v = 0; v < owner.size(); ++v)
      if (owner[v] < 0) owner[v] = nearest[v];
  }
  const std::vector<int> carriers = jointCarriers(skeleton);
  SkinWeights weights;
  weights.vertices.resize(restVertices.size());
  for (size_t v = 0; v < restVertices.size(); ++v) {
    const int k = owner[v];
    const BodyPart& part = skeleton.parts[k];
    const Vec3& p = restVertices[v];
    const Vec3 bone = skeleton.joints[part.to].position - skeleton.joints[part.from].position;
    const double length = bone.norm();
    auto& influences = weights.vertices[v];
    influences[0] = {k, 1.0};
    if (!(length > 0.0)) continue;
    const double s = (p - skeleton.joints[part.from].position).dot(bone) / length;  // along the bone
    const int before = carriers[part.from] != k ? carriers[part.from] : -1;
    const int after = partStartingAt(skeleton, part.to, k, p);
    double wBefore = before >= 0 ? smoothstep((-s + blendRadius) / (2.0 * blendRadius)) : 0.0;
    double wAfter = after >= 0 ? smoothstep((s - length + blendRadius) / (2.0 * blendRadius)) : 0.0;
    if (wBefore + wAfter > 1.0) {  // a part shorter than the blend: both ends share it out
      const double total = wBefore + wAfter;
      wBefore /= total, wAfter /= total;
    }
    if (before >= 0 && before == after) wBefore += wAfter, wAfter = 0.0;
    influences[0].weight = 1.0 - wBefore - wAfter;
    if (wBefore > 0.0) influences[1] = {before, wBefore};
    if (wAfter > 0.0) influences[2] = {after, wAfter};
  }
  return weights;
}

std::vector<Vec3> skin(const SkinWeights& weights, const std::vector<Eigen::Affine3d>& partTransforms,
                       const std::vector<Vec3>& restVertices) {
  if (weights.vertices.size() != restVertices.size())
    throw std::invalid_argument("weights: " + std::to_string(weights.vertices.size()) +
                                " vertices, restVertices: " + std::to_string(restVertices.size()));
  std::vector<Vec3> posed(restVertices.size());
  for (size_t v = 0; v < restVertices.size(); ++v) {
    const Vec3& p = restVertices[v];
    Vec3 moved = Vec3::Zero();
    for (const SkinWeights::Influence& influence : weights.vertices[v]) {
      if (influence.part < 0 || influence.weight == 0.0) continue;
      if (influence.part >= static_cast<int>(partTransforms.size()))
        throw std::invalid_argument("vertex " + std::to_string(v) + ": part " + std::to_string(influence.part) +
                                    " has no transform (" + std::to_string(partTransforms.size()) + " given)");
      moved += influence.weight * (partTransforms[influence.part] * p - p);
    }
    posed[v] = p + moved;
  }
  return posed;
}

}  // namespace figment
