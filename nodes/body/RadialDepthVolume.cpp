#include "nodes/body/RadialDepthVolume.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "nodes/NodeSource.h"
#include "sim/collision/CollisionVolume.h"
#include "sim/collision/RadialDepth.h"

FIGMENT_DERIVED_NODE_SOURCE(RadialDepthVolume, CollisionVolumeNode)

RadialDepthVolume::RadialDepthVolume() {
  SO_NODE_CONSTRUCTOR(RadialDepthVolume);
  SO_NODE_ADD_FIELD(base, (0.0f, 0.0f, 0.0f));
  SO_NODE_ADD_FIELD(direction, (0.0f, 1.0f, 0.0f));
  SO_NODE_ADD_FIELD(reference, (1.0f, 0.0f, 0.0f));
  SO_NODE_ADD_FIELD(length, (1.0f));
  SO_NODE_ADD_FIELD(harmonics, (0));
  SO_NODE_ADD_EMPTY_MFIELD(coefficients);
}

RadialDepthVolume::~RadialDepthVolume() = default;

namespace {

figment::Vec3 toVec3(const SbVec3f& v) {
  return {v[0], v[1], v[2]};
}
SbVec3f toSb(const figment::Vec3& v) {
  return SbVec3f(float(v.x()), float(v.y()), float(v.z()));
}

}  // namespace

figment::RadialDepthParameters RadialDepthVolume::parameters() const {
  figment::RadialDepthParameters p;
  p.base = toVec3(base.getValue());
  p.direction = toVec3(direction.getValue());
  p.length = length.getValue();
  p.harmonics = harmonics.getValue();
  if (p.direction.norm() == 0.0) throw std::invalid_argument(label() + ": direction = 0 0 0 is not an axis");
  p.direction.normalize();
  // The reference made perpendicular to the axis (written values are rounded floats).
  const figment::Vec3 r = toVec3(reference.getValue());
  p.reference = r - r.dot(p.direction) * p.direction;
  if (p.reference.norm() < 1e-6 * std::max(r.norm(), 1e-30))
    throw std::invalid_argument(label() + ": reference is parallel to direction");
  p.reference.normalize();
  if (p.harmonics < 0)
    throw std::invalid_argument(label() + ": harmonics = " + std::to_string(p.harmonics) + " must be >= 0");
  const int perSection = 2 * p.harmonics + 1;
  const int values = coefficients.getNum();
  if (values % perSection != 0 || values / perSection < 2)
    throw std::invalid_argument(
        label() + ": coefficients has " + std::to_string(values) +
        " values, not a multiple (>= 2 sections) of 2 harmonics + 1 = " + std::to_string(perSection));
  for (int j = 0; j < values / perSection; ++j) {
    std::vector<double> section;
    for (int k = 0; k < perSection; ++k) section.push_back(coefficients[j * perSection + k]);
    p.coefficients.push_back(std::move(section));
  }
  try {
    p.validate();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(label() + ": " + e.what());
  }
  return p;
}

void RadialDepthVolume::setParameters(const figment::RadialDepthParameters& p) {
  const bool notifying = enableNotify(FALSE);  // one notification for the lot
  base = toSb(p.base);
  direction = toSb(p.direction);
  reference = toSb(p.reference);
  length = float(p.length);
  harmonics = p.harmonics;
  coefficients.setNum(0);
  int n = 0;
  for (const auto& section : p.coefficients)
    for (double c : section) coefficients.set1Value(n++, float(c));
  enableNotify(notifying);
  touch();
}

std::shared_ptr<const figment::CollisionVolume> RadialDepthVolume::makeVolume(const figment::TriangleMesh&) const {
  return figment::makeVolume(parameters());
}

std::vector<CollisionVolumeNode::Polyline> RadialDepthVolume::wireframe() const {
  const figment::RadialDepth volume(parameters());
  const double axisLength = volume.parameters().length;
  const int sections = static_cast<int>(volume.parameters().coefficients.size());
  constexpr int meridians = 8, ringSegments = 48;
  const double pi = std::numbers::pi;
  std::vector<Polyline> lines;
  // A ring per section, meridians along the axis (closed across the caps at both ends).
  for (int j = 0; j < sections; ++j) {
    const double s = axisLength * j / (sections - 1);
    Polyline ring;
    for (int i = 0; i <= ringSegments; ++i) ring.push_back(volume.surface(s, 2 * pi * i / ringSegments).cast<float>());
    lines.push_back(std::move(ring));
  }
  const figment::Vec3 axis = volume.parameters().direction;
  const figment::Vec3 start = volume.parameters().base;
  for (int m = 0; m < meridians; ++m) {
    const double a = 2 * pi * m / meridians;
    Polyline line{start.cast<float>()};
    for (int j = 0; j < sections; ++j) line.push_back(volume.surface(axisLength * j / (sections - 1), a).cast<float>());
    line.push_back((start + axisLength * axis).cast<float>());
    lines.push_back(std::move(line));
  }
  return lines;
}
