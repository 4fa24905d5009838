#include "sim/pattern/PatternPlacement.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/body/BodySlices.h"
#include "sim/body/BodyStance.h"
#include "sim/pattern/LimbClearance.h"
#include "sim/pattern/ShoulderRest.h"

namespace figment {

namespace {
constexpr double kWaistShare = 0.6;  // of the stature: where the torso's centre is taken
// m: how far a sleeve's panel starts clear of the arm it is placed along (LimbClearance.h).
// Measured, not derived: the 56 shipped sleeved patterns (T-shirts, shirts, dresses) sewn on
// their chart bodies came out clean in 53 sizes with 1 cm, in 51 with 2 cm; the sewing of
// the largest women's shirts is that sensitive to where it starts (docs/patterns.md).
constexpr double kArmClearance = 0.01;
}  // namespace

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
  placement.axis =
      waist.empty() ? Vec2(0.5 * (box.min.x() + box.max.x()), 0.5 * (box.min.z() + box.max.z())) : waist.centroid();
  placement.armAngle = armAngleOf(body);
  placement.surface = std::make_shared<TriangleMesh>(body);
  return placement;
}

double armAngleOf(const TriangleMesh& body) {
  const Bounds box = boundsOf(body.vertices);
  const double stature = box.size().y(), centre = 0.5 * (box.min.x() + box.max.x());
  // The outermost x of each 1 cm band: the left arm's outer contour, where it hangs free.
  constexpr int kBands = 16;
  std::vector<double> outer(kBands, -1e9);
  const double low = box.min.y() + 0.62 * stature, high = box.min.y() + 0.78 * stature;
  for (const Vec3& v : body.vertices) {
    if (v.y() < low || v.y() >= high) continue;
    const int band = std::min(kBands - 1, static_cast<int>((v.y() - low) / (high - low) * kBands));
    outer[band] = std::max(outer[band], v.x() - centre);
  }
  // Least squares x = a + b y over the bands.
  double n = 0, sy = 0, sx = 0, syy = 0, sxy = 0;
  for (int k = 0; k < kBands; ++k) {
    if (outer[k] < -1e8) continue;
    const double y = low + (k + 0.5) * (high - low) / kBands, x = outer[k];
    n += 1, sy += y, sx += x, syy += y * y, sxy += x * y;
  }
  if (n < kBands / 2) return 0.0;
  const double slope = (n * sxy - sx * sy) / (n * syy - sy * sy);  // dx/dy: < 0, the arm goes out as it goes down
  if (!(slope < -0.05)) return 0.0;                                // arms along the body: no angle to match
  return std::atan2(1.0, -slope) * 180.0 / M_PI;
}

namespace {

// The angle (degrees) of a rotation about z alone; NaN for any other rotation.
double zAngle(const Eigen::Matrix3d& r) {
  if (std::abs(r(2, 2) - 1.0) > 1e-9) return std::nan("");
  return std::atan2(r(1, 0), r(0, 0)) * 180.0 / M_PI;
}

// The pattern's arm angle below the horizontal: its panels turned furthest about z (a
// sleeve along the left arm is turned by minus that angle); 0 when none is turned past 20.
double patternArmAngle(const SewingPattern& pattern) {
  double most = 0.0;
  for (const Panel& panel : pattern.panels) {
    const double a = std::abs(zAngle(panel.rotation));
    if (std::isfinite(a) && a > 20.0 && a < 80.0) most = std::max(most, a);
  }
  return most;
}

// Turns `panel` by `degrees` about z through its placed point nearest the body's axis
// (its armhole's end).
void turnAboutArmhole(Panel& panel, double degrees, double axisX) {
  Vec3 pivot = panel.translation;
  double nearest = std::numeric_limits<double>::infinity();
  for (const Vec2& p : panel.vertices) {
    const Vec3 placedPoint = panel.rotation * Vec3(p.x(), p.y(), 0.0) + panel.translation;
    if (std::abs(placedPoint.x() - axisX) < nearest) nearest = std::abs(placedPoint.x() - axisX), pivot = placedPoint;
  }
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(degrees * M_PI / 180.0, Vec3::UnitZ()).toRotationMatrix();
  panel.rotation = turn * panel.rotation;
  panel.translation = turn * (panel.translation - pivot) + pivot;
}

}  // namespace

SewingPattern placed(const SewingPattern& pattern, const PatternPlacement& placement) {
  SewingPattern out = pattern;
  for (Panel& panel : out.panels) panel.translation = placement(panel.translation);
  // The panels along the arms: turned about z by about the pattern's arm angle.
  const double patternAngle = patternArmAngle(pattern);
  std::vector<Panel*> arms;
  for (Panel& panel : out.panels) {
    const double a = zAngle(panel.rotation);
    if (patternAngle > 0.0 && std::isfinite(a) && std::abs(std::abs(a) - patternAngle) <= 10.0) arms.push_back(&panel);
  }
  if (placement.armAngle > 0.0)
    for (Panel* panel : arms) {
      // A left sleeve (+x) is turned by -angle: lowering it turns it further clockwise.
      const double lower = placement.armAngle - patternAngle;
      turnAboutArmhole(*panel, zAngle(panel->rotation) < 0.0 ? -lower : lower, placement.axis.x());
    }
  if (!placement.surface) return out;
  // After the sleeves are turned: they rise with the rest, their armholes staying on the
  // torso's; then each moves clear of the arm it is placed along (LimbClearance.h).
  const double rise = shoulderRise(out, *placement.surface);
  for (Panel& panel : out.panels) panel.translation.y() += rise;
  for (Panel* panel : arms) moveClearOf(*panel, *placement.surface, kArmClearance);
  return out;
}

}  // namespace figment
