#include "session/FrameDisplay.h"

#include <Inventor/fields/SoMFVec3f.h>
#include <Inventor/lists/SoFieldList.h>
#include <Inventor/nodes/SoNode.h>

#include "nodes/body/CollisionBody.h"

namespace figment::session {

void showPositions(ClothEngine& engine, const std::vector<SbVec3f>& positions) {
  SoFieldList fed;
  engine.positions.getForwardConnections(fed);
  for (int i = 0; i < fed.getLength(); ++i) {
    SoField* field = fed[i];
    if (!field->isOfType(SoMFVec3f::getClassTypeId())) continue;
    SoFieldContainer* container = field->getContainer();
    if (container && container->isOfType(SoNode::getClassTypeId()) && asCollisionBody(static_cast<SoNode*>(container)))
      continue;
    field->enableConnection(FALSE);
    auto* points = static_cast<SoMFVec3f*>(field);
    points->setNum(static_cast<int>(positions.size()));
    points->setValues(0, static_cast<int>(positions.size()), positions.data());
  }
}

}  // namespace figment::session
