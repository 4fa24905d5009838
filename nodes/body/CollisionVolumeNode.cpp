#include "nodes/body/CollisionVolumeNode.h"

#include <GL/gl.h>
#include <Inventor/SbBox3f.h>
#include <Inventor/SoPrimitiveVertex.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/bundles/SoMaterialBundle.h>
#include <Inventor/elements/SoGLLazyElement.h>
#include <Inventor/elements/SoLightModelElement.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/misc/SoNotification.h>
#include <Inventor/misc/SoState.h>

#include <stdexcept>

SO_NODE_ABSTRACT_SOURCE(CollisionVolumeNode);

void CollisionVolumeNode::initClass() {
  if (classTypeId != SoType::badType()) return;
  SO_NODE_INIT_ABSTRACT_CLASS(CollisionVolumeNode, SoShape, "Shape");
}

CollisionVolumeNode::CollisionVolumeNode() {
  SO_NODE_CONSTRUCTOR(CollisionVolumeNode);
  SO_NODE_ADD_FIELD(part, (""));
}

CollisionVolumeNode::~CollisionVolumeNode() = default;

std::string CollisionVolumeNode::label() const {
  std::string text = getTypeId().getName().getString();
  if (getName().getLength() > 0) text += " '" + std::string(getName().getString()) + "'";
  return text;
}

const std::vector<CollisionVolumeNode::Polyline>& CollisionVolumeNode::cachedWireframe() const {
  if (wireframeValid_) return wireframe_;
  try {
    wireframe_ = wireframe();
  } catch (const std::exception& e) {
    SoDebugError::postWarning("CollisionVolumeNode", "%s: %s", label().c_str(), e.what());
    wireframe_.clear();
  }
  wireframeValid_ = true;
  return wireframe_;
}

void CollisionVolumeNode::notify(SoNotList* list) {
  wireframeValid_ = false;
  inherited::notify(list);
}

void CollisionVolumeNode::GLRender(SoGLRenderAction* action) {
  if (!shouldGLRender(action)) return;
  SoState* state = action->getState();
  state->push();
  // Lines in the current colour: no lighting (they have no normals).
  SoLightModelElement::set(state, this, SoLightModelElement::BASE_COLOR);
  SoMaterialBundle material(action);
  material.sendFirst();
  for (const Polyline& line : cachedWireframe()) {
    glBegin(GL_LINE_STRIP);
    for (const Eigen::Vector3f& p : line) glVertex3f(p.x(), p.y(), p.z());
    glEnd();
  }
  state->pop();
}

void CollisionVolumeNode::generatePrimitives(SoAction* action) {
  SoPrimitiveVertex a, b;
  for (const Polyline& line : cachedWireframe())
    for (size_t i = 1; i < line.size(); ++i) {
      a.setPoint(SbVec3f(line[i - 1].x(), line[i - 1].y(), line[i - 1].z()));
      b.setPoint(SbVec3f(line[i].x(), line[i].y(), line[i].z()));
      invokeLineSegmentCallbacks(action, &a, &b);
    }
}

void CollisionVolumeNode::computeBBox(SoAction*, SbBox3f& box, SbVec3f& center) {
  box.makeEmpty();
  for (const Polyline& line : cachedWireframe())
    for (const Eigen::Vector3f& p : line) box.extendBy(SbVec3f(p.x(), p.y(), p.z()));
  if (!box.isEmpty()) center = box.getCenter();
}
