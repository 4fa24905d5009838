#include "sim/pattern/PatternPlacement.h"

#include <stdexcept>
#include <string>

#include "sim/body/BodySlices.h"
#include "sim/body/BodyStance.h"

namespace figment {

namespace {
constexpr double kWaistShare = 0.6;  // of the stature: where the torso's centre is taken
}

PatternPlacement placementOn(const TriangleMesh& body, double madeForStature) {
  if (body.vertices.empty()) throw std::invalid_argument("the body to place the pattern on has no vertices");
  const Bounds box = boundsOf(body.vertices);
  const double stature = box.size().y();
  if (stature < kMinStature || stature > kMaxStature)
    throw std::invalid_argument("the body's stature " + std::to_string(stature) + " m is out of [" +
                                std::to_string(kMinStature) + ", " + std::to_string(kMaxStature) + "] m");
  if (madeForStature != 0.0 && (madeForStature < kMinStature || madeForStature > kMaxStature))
    throw std::invalid_argument("the pattern's body stature " + std::to_string(madeForStature) + " m is out of [" +
                                std::to_string(kMinStature) + ", " + std::to_string(kMaxStature) + "] m");
  PatternPlacement placement;
  placement.feet = box.min.y();
  placement.heightScale = madeForStature > 0.0 ? stature / madeForStature : 1.0;
  const SliceOptions options = centredSlicing(body, 0.04, 0.12);
  const TorsoSlice waist = sliceTorso(body, box.min.y() + kWaistShare * stature, options);
  placement.axis = waist.empty() ? Vec2(0.5 * (box.min.x() + box.max.x()), 0.5 * (box.min.z() + box.max.z()))
                                 : waist.centroid();
  return placement;
}

SewingPattern placed(const SewingPattern& pattern, const PatternPlacement& placement) {
  SewingPattern out = pattern;
  for (Panel& panel : out.panels) panel.translation = placement(panel.translation);
  return out;
}

}  // namespace figment
