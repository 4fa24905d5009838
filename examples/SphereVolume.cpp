#include "SphereVolume.h"

#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/actions/SoRayPickAction.h>
#include <Inventor/elements/SoModelMatrixElement.h>
#include <Inventor/misc/SoState.h>

#include <stdexcept>
#include <string>

#include "SphereCollider.h"

SO_NODE_SOURCE(SphereVolume);

void SphereVolume::initClass() {
  // Coin calls this itself when it loads the library for an unknown "SphereVolume";
  // a second call (the program registered it already) must do nothing.
  if (getClassTypeId() != SoType::badType()) return;
  SO_NODE_INIT_CLASS(SphereVolume, SoSphere, "Sphere");
}

SphereVolume::SphereVolume() {
  SO_NODE_CONSTRUCTOR(SphereVolume);
  SO_NODE_ADD_FIELD(center, (0.0f, 0.0f, 0.0f));
}

SphereVolume::~SphereVolume() = default;

std::shared_ptr<const figment::Collider> SphereVolume::bodyCollider() const {
  const float r = radius.getValue();
  if (!(r > 0.0f)) {
    const SbName name = getName();
    throw std::invalid_argument(std::string("SphereVolume") +
                                (name.getLength() ? " '" + std::string(name.getString()) + "'" : "") +
                                ": radius = " + std::to_string(r) + " must be > 0");
  }
  const SbVec3f& c = center.getValue();
  return std::make_shared<SphereCollider>(figment::Vec3(c[0], c[1], c[2]), r);
}

figment::CollisionBody::Description SphereVolume::describeBody() const {
  return {"sphere", {}};
}

namespace {

// Applies `draw` (the Sphere's own action) with the model matrix moved to `centre`, the
// state restored afterwards.
template <class Action, class Draw>
void atCentre(Action* action, SoNode* node, const SbVec3f& centre, Draw draw) {
  SoState* state = action->getState();
  state->push();
  SoModelMatrixElement::translateBy(state, node, centre);
  draw();
  state->pop();
}

}  // namespace

void SphereVolume::GLRender(SoGLRenderAction* action) {
  atCentre(action, this, center.getValue(), [&] { inherited::GLRender(action); });
}
void SphereVolume::getBoundingBox(SoGetBoundingBoxAction* action) {
  atCentre(action, this, center.getValue(), [&] { inherited::getBoundingBox(action); });
}
void SphereVolume::rayPick(SoRayPickAction* action) {
  atCentre(action, this, center.getValue(), [&] { inherited::rayPick(action); });
}
void SphereVolume::callback(SoCallbackAction* action) {
  atCentre(action, this, center.getValue(), [&] { inherited::callback(action); });
}
