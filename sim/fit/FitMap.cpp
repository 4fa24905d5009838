#include "sim/fit/FitMap.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sim/collision/TriangleBvh.h"

namespace figment {

FitMapKind fitMapKind(const std::string& name) {
  if (name == "stretch") return FitMapKind::Stretch;
  if (name == "ease") return FitMapKind::Ease;
  if (name == "pressure") return FitMapKind::Pressure;
  throw std::invalid_argument("fit map '" + name + "' is not stretch, ease or pressure");
}

std::vector<double> fitMapValues(const FitInput& input, FitMapKind kind) {
  if (kind == FitMapKind::Pressure) return contactPressures(input);
  const std::vector<Vec3>& x = *input.positions;
  std::vector<double> values(x.size(), 0.0);
  if (kind == FitMapKind::Ease) {
    for (size_t i = 0; i < x.size(); ++i)
      values[i] =
          std::max(0.0, std::sqrt(input.body->bvh().closest(x[i]).distanceSquared) - input.parameters.clearance);
    return values;
  }
  std::vector<double> weight(x.size(), 0.0);
  for (const Triangle& t : input.rest->triangles) {
    const Vec3 &a = input.rest->vertices[t[0]], &b = input.rest->vertices[t[1]], &c = input.rest->vertices[t[2]];
    const double area = 0.5 * (b - a).cross(c - a).norm();
    if (area <= 0) continue;
    const double strain = largestPrincipalStrain(a, b, c, x[t[0]], x[t[1]], x[t[2]]);
    for (int k = 0; k < 3; ++k) values[t[k]] += area * strain, weight[t[k]] += area;
  }
  for (size_t i = 0; i < x.size(); ++i)
    if (weight[i] > 0) values[i] /= weight[i];
  return values;
}

double fitMapShare(double value, FitMapKind kind, const FabricLimits& limits) {
  double share = 0;
  switch (kind) {
    case FitMapKind::Stretch:
      share = value / limits.stretch;
      break;
    case FitMapKind::Pressure:
      share = value / limits.pressure;
      break;
    case FitMapKind::Ease:
      share = 1.0 - value / kEaseMapRange;
      break;
  }
  return std::clamp(share, 0.0, 1.0);
}

int fitMapBand(double share) {
  return std::clamp(static_cast<int>(std::floor(share * kFitMapBands)), 0, kFitMapBands - 1);
}

Vec3 fitMapColour(int band) {
  // HSV with s = v = 1: the hue's sextant and where in it.
  const double hue = 240.0 * (1.0 - static_cast<double>(band) / (kFitMapBands - 1));
  const double h = hue / 60.0;
  const double f = h - std::floor(h);
  switch (static_cast<int>(std::floor(h)) % 6) {
    case 0:
      return Vec3(1, f, 0);  // red to yellow
    case 1:
      return Vec3(1 - f, 1, 0);  // yellow to green
    case 2:
      return Vec3(0, 1, f);  // green to cyan
    case 3:
      return Vec3(0, 1 - f, 1);  // cyan to blue
    default:
      return Vec3(0, 0, 1);  // blue (hue 240)
  }
}

std::vector<int> fitMapBands(const FitInput& input, FitMapKind kind, const FabricLimits& limits) {
  std::vector<int> bands;
  for (const double value : fitMapValues(input, kind)) bands.push_back(fitMapBand(fitMapShare(value, kind, limits)));
  return bands;
}

}  // namespace figment
