#include "nodes/cloth/GarmentSurface.h"

#include <cmath>
#include <stdexcept>

#include "nodes/NodeSource.h"
#include "nodes/cloth/ClothEngineInputs.h"
#include "sim/collision/MeshCollider.h"
#include "sim/collision/OffsetCollider.h"

FIGMENT_NODE_SOURCE(GarmentSurface, SoNode, "Node")

GarmentSurface::GarmentSurface() {
  SO_NODE_CONSTRUCTOR(GarmentSurface);
  SO_NODE_ADD_FIELD(point, (0.0f, 0.0f, 0.0f));
  point.setNum(0);
  point.setDefault(TRUE);
  SO_NODE_ADD_FIELD(coordIndex, (-1));
  coordIndex.setNum(0);
  coordIndex.setDefault(TRUE);
  SO_NODE_ADD_FIELD(thickness, (0.001f));
}

GarmentSurface::~GarmentSurface() = default;

std::string GarmentSurface::label() const {
  return getName().getLength() > 0 ? "GarmentSurface '" + std::string(getName().getString()) + "'" : "GarmentSurface";
}

std::shared_ptr<const figment::Collider> GarmentSurface::bodyCollider() const {
  if (collider_) return collider_;
  try {
    const double offset = thickness.getValue();
    if (!(offset >= 0.0) || !std::isfinite(offset))
      throw std::invalid_argument("thickness = " + std::to_string(offset) + " must be finite and >= 0");
    figment::TriangleMesh surface = figment::garmentFromFields(point, coordIndex, "point");
    for (const figment::Vec3& x : surface.vertices)
      if (!x.allFinite()) throw std::invalid_argument("point has a value that is not finite");
    auto mesh = std::make_shared<const figment::MeshCollider>(std::move(surface), figment::OpenEdges::Outside);
    collider_ = std::make_shared<const figment::OffsetCollider>(mesh, offset);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(label() + ": " + e.what());
  }
  return collider_;
}

figment::CollisionBody::Description GarmentSurface::describeBody() const {
  return {"garment surface", {{"points", point.getNum()}}};
}

void GarmentSurface::notify(SoNotList* list) {
  collider_.reset();  // the inner garment draped again, or a field changed
  inherited::notify(list);
}
