#include "nodes/FaceIndexCheck.h"

#include "nodes/CoordIndexFaces.h"

#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/elements/SoCoordinateElement.h>
#include <Inventor/nodes/SoIndexedShape.h>
#include <Inventor/nodes/SoVertexProperty.h>

namespace figment {

namespace {

// How many coordinates `shape` indexes: its own vertexProperty's when it has some (as
// Coin draws it), else the current coordinates.
int coordinateCount(const SoIndexedShape& shape, SoState* state) {
  const SoNode* properties = shape.vertexProperty.getValue();
  if (properties && properties->isOfType(SoVertexProperty::getClassTypeId())) {
    const int own = static_cast<const SoVertexProperty*>(properties)->vertex.getNum();
    if (own > 0) return own;
  }
  return SoCoordinateElement::getInstance(state)->getNum();
}

std::string label(const SoNode& node) {
  const std::string type = node.getTypeId().getName().getString();
  const SbName name = node.getName();
  return name.getLength() ? type + " '" + name.getString() + "'" : type;
}

SoCallbackAction::Response checkShape(void* data, SoCallbackAction* action, const SoNode* node) {
  const auto& shape = *static_cast<const SoIndexedShape*>(node);
  const int points = coordinateCount(shape, action->getState());
  const int32_t* index = shape.coordIndex.getValues(0);
  const int bad = firstBadIndex(index, shape.coordIndex.getNum(), points);
  if (bad < 0) return SoCallbackAction::PRUNE;  // nothing to generate: no primitive callbacks
  std::string& error = *static_cast<std::string*>(data);
  error = label(shape) + ": coordIndex[" + std::to_string(bad) + "] = " + std::to_string(index[bad]);
  error += index[bad] < -1 ? " is neither a vertex nor the -1 that ends a face"
                           : " is not a vertex: the coordinates have " + std::to_string(points) + " points";
  return SoCallbackAction::ABORT;
}

}  // namespace

std::string firstFaceIndexError(SoNode* root) {
  std::string error;
  SoCallbackAction action;
  action.addPreCallback(SoIndexedShape::getClassTypeId(), checkShape, &error);
  action.apply(root);
  return error;
}

}  // namespace figment
