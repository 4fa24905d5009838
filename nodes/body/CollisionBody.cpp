#include "nodes/body/CollisionBody.h"

#include <Inventor/nodes/SoNode.h>

namespace figment {

// Defined here, so the interface's type information lives once, in figment_nodes.
CollisionBody::~CollisionBody() = default;

const CollisionBody* asCollisionBody(const SoNode* node) {
  return dynamic_cast<const CollisionBody*>(node);
}

}  // namespace figment
