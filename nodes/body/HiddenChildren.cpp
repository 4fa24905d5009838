#include "nodes/body/HiddenChildren.h"

#include <Inventor/actions/SoAction.h>
#include <Inventor/misc/SoChildList.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoSeparator.h>

namespace figment {

HiddenMesh appendHiddenMesh(SoChildList& children) {
  auto* root = new SoSeparator;
  HiddenMesh mesh{new SoCoordinate3, new SoIndexedFaceSet};
  mesh.coordinates->point.setNum(0);
  root->addChild(mesh.coordinates);
  root->addChild(mesh.faces);
  children.append(root);
  return mesh;
}

void traverseHidden(SoChildList& children, SoAction* action) {
  int numIndices = 0;
  const int* indices = nullptr;
  if (action->getPathCode(numIndices, indices) == SoAction::IN_PATH)
    children.traverseInPath(action, numIndices, indices);
  else
    children.traverse(action);
}

}  // namespace figment
