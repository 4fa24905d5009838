#include "nodes/body/ExactVolume.h"

#include <stdexcept>

#include "nodes/NodeSource.h"
#include "sim/collision/CollisionVolume.h"
#include "sim/core/TriangleMesh.h"

FIGMENT_DERIVED_NODE_SOURCE(ExactVolume, CollisionVolumeNode)

ExactVolume::ExactVolume() {
  SO_NODE_CONSTRUCTOR(ExactVolume);
}

ExactVolume::~ExactVolume() = default;

std::shared_ptr<const figment::CollisionVolume> ExactVolume::makeVolume(
    const figment::TriangleMesh& partTriangles) const {
  if (partTriangles.triangles.empty())
    throw std::invalid_argument(label() + ": part = \"" + std::string(part.getValue().getString()) +
                                "\" has no triangles in the body");
  return figment::makeVolume(partTriangles);
}
