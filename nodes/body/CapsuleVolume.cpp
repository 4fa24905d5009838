#include "nodes/body/CapsuleVolume.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "nodes/NodeSource.h"
#include "sim/collision/Capsule.h"
#include "sim/collision/CollisionVolume.h"

FIGMENT_DERIVED_NODE_SOURCE(CapsuleVolume, CollisionVolumeNode)

CapsuleVolume::CapsuleVolume() {
  SO_NODE_CONSTRUCTOR(CapsuleVolume);
  SO_NODE_ADD_FIELD(r1, (1.0f));
  SO_NODE_ADD_FIELD(r2, (1.0f));
  SO_NODE_ADD_FIELD(tx, (0.0f));
  SO_NODE_ADD_FIELD(tz, (0.0f));
  SO_NODE_ADD_FIELD(x, (1.0f));
  SO_NODE_ADD_FIELD(y, (1.0f));
  SO_NODE_ADD_FIELD(z, (1.0f));
  SO_NODE_ADD_FIELD(ox, (0.0f));
  SO_NODE_ADD_FIELD(oy, (0.0f));
  SO_NODE_ADD_FIELD(oz, (0.0f));
  SO_NODE_ADD_FIELD(theta, (0.0f));
  SO_NODE_ADD_FIELD(phi, (0.0f));
}

CapsuleVolume::~CapsuleVolume() = default;

figment::CapsuleParameters CapsuleVolume::parameters() const {
  figment::CapsuleParameters p;
  p.r1 = r1.getValue(), p.r2 = r2.getValue(), p.tx = tx.getValue(), p.tz = tz.getValue();
  p.x = x.getValue(), p.y = y.getValue(), p.z = z.getValue();
  p.ox = ox.getValue(), p.oy = oy.getValue(), p.oz = oz.getValue();
  p.theta = theta.getValue(), p.phi = phi.getValue();
  return p;
}

void CapsuleVolume::setParameters(const figment::CapsuleParameters& p) {
  const bool notifying = enableNotify(FALSE);  // one notification for all twelve
  r1 = float(p.r1), r2 = float(p.r2), tx = float(p.tx), tz = float(p.tz);
  x = float(p.x), y = float(p.y), z = float(p.z);
  ox = float(p.ox), oy = float(p.oy), oz = float(p.oz);
  theta = float(p.theta), phi = float(p.phi);
  enableNotify(notifying);
  touch();
}

std::shared_ptr<const figment::CollisionVolume> CapsuleVolume::makeVolume(const figment::TriangleMesh&) const {
  const figment::CapsuleParameters p = parameters();
  try {
    p.validate();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(label() + ": " + e.what());
  }
  return figment::makeVolume(p);
}

std::vector<CollisionVolumeNode::Polyline> CapsuleVolume::wireframe() const {
  const figment::CapsuleParameters p = parameters();
  p.validate();
  const figment::Capsule capsule(p);
  // Meridians every 45 degrees and rings along the profile (t in [0, 3]).
  constexpr int meridians = 8, ringSegments = 32, profileSteps = 36, rings = 11;
  const double pi = std::numbers::pi;
  std::vector<Polyline> lines;
  for (int m = 0; m < meridians; ++m) {
    Polyline line;
    for (int i = 0; i <= profileSteps; ++i)
      line.push_back(capsule.surface(3.0 * i / profileSteps, 2 * pi * m / meridians).cast<float>());
    lines.push_back(std::move(line));
  }
  for (int r = 1; r <= rings; ++r) {
    Polyline line;
    for (int i = 0; i <= ringSegments; ++i)
      line.push_back(capsule.surface(3.0 * r / (rings + 1), 2 * pi * i / ringSegments).cast<float>());
    lines.push_back(std::move(line));
  }
  return lines;
}
