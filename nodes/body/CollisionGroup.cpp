#include "nodes/body/CollisionGroup.h"

#include <stdexcept>
#include <string>

#include "nodes/NodeSource.h"
#include "sim/collision/CompositeCollider.h"

FIGMENT_NODE_SOURCE(CollisionGroup, SoNode, "Node")

CollisionGroup::CollisionGroup() {
  SO_NODE_CONSTRUCTOR(CollisionGroup);
  SO_NODE_ADD_FIELD(body, (nullptr));
  SO_NODE_ADD_FIELD(layers, (nullptr));
  layers.setNum(0);
  layers.setDefault(TRUE);
}

CollisionGroup::~CollisionGroup() = default;

std::string CollisionGroup::label() const {
  return getName().getLength() > 0 ? "CollisionGroup '" + std::string(getName().getString()) + "'" : "CollisionGroup";
}

std::shared_ptr<const figment::Collider> CollisionGroup::bodyCollider() const {
  return collider(true);
}

std::shared_ptr<const figment::Collider> CollisionGroup::layersCollider() const {
  return collider(false);
}

std::shared_ptr<const figment::Collider> CollisionGroup::collider(bool withBody) const {
  // Built on each call: a member's collider is kept by the member itself, and a
  // GarmentSurface's changes whenever its garment drapes again.
  auto group = std::make_shared<figment::CompositeCollider>();
  const auto add = [&](const SoNode* node, const std::string& field) {
    const std::string entry = label() + ": " + field;
    if (node == this) throw std::invalid_argument(entry + " is the group itself");
    const figment::CollisionBody* member = figment::asCollisionBody(node);
    if (!member)
      throw std::invalid_argument(entry + " is " + node->getTypeId().getName().getString() +
                                  ", not a collision body (Mannequin, MeshFile, GarmentSurface, CollisionGroup)");
    try {
      group->add(member->bodyCollider());
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(entry + ": " + e.what());
    }
  };
  if (withBody && body.getValue()) add(body.getValue(), "body");
  for (int i = 0; i < layers.getNum(); ++i)
    if (layers[i]) add(layers[i], "layers[" + std::to_string(i) + "]");
  if (!withBody) return group->parts().empty() ? nullptr : group;
  if (group->parts().empty()) throw std::invalid_argument(label() + ": body and layers are empty");
  return group;
}

figment::CollisionBody::Description CollisionGroup::describeBody() const {
  return {"group", {{"bodies", (body.getValue() ? 1 : 0) + layers.getNum()}}};
}
