#include "nodes/render/GLStencilElement.h"

#include <GL/gl.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/misc/SoState.h>

#include "nodes/NodeSource.h"
#include "nodes/render/StencilDecisionElement.h"
#include "nodes/render/StencilRuleElement.h"

FIGMENT_ELEMENT_SOURCE(GLStencilElement)

GLStencilElement::~GLStencilElement() = default;

void initStencilElements() {
  GLStencilElement::initClass();
  StencilRuleElement::initClass();
  StencilDecisionElement::initClass();
}

void GLStencilElement::init(SoState* state) {
  inherited::init(state);
  mode_ = OFF;
  clearedEachFrame_ = false;
}

void GLStencilElement::push(SoState* state) {
  inherited::push(state);
  mode_ = static_cast<const GLStencilElement*>(getNextInStack())->mode_;
}

void GLStencilElement::pop(SoState* state, const SoElement* previousTop) {
  // previousTop is the element being popped; this one is the state below it.
  if (static_cast<const GLStencilElement*>(previousTop)->mode_ != mode_) updateGL();
  inherited::pop(state, previousTop);
}

SbBool GLStencilElement::matches(const SoElement* element) const {
  return static_cast<const GLStencilElement*>(element)->mode_ == mode_;
}

SoElement* GLStencilElement::copyMatchInfo() const {
  auto* copy = static_cast<GLStencilElement*>(getTypeId().createInstance());
  copy->mode_ = mode_;
  return copy;
}

void GLStencilElement::set(SoState* state, Mode mode) {
  auto* element = static_cast<GLStencilElement*>(state->getElement(classStackIndex));
  if (element == nullptr || element->mode_ == mode) return;
  element->mode_ = mode;
  element->updateGL();
}

GLStencilElement::Mode GLStencilElement::get(SoState* state) {
  const auto* element = static_cast<const GLStencilElement*>(state->getConstElement(classStackIndex));
  return element ? element->mode_ : OFF;
}

void GLStencilElement::updateGL() const {
  // (test function, reference, bits compared, bits written)
  auto use = [](GLenum function, GLuint reference, GLuint compared, GLuint written) {
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(function, static_cast<GLint>(reference), compared);
    glStencilMask(written);
    glStencilOp(GL_KEEP, GL_KEEP, written ? GL_REPLACE : GL_KEEP);
  };
  switch (mode_) {
    case OFF:
      glDisable(GL_STENCIL_TEST);
      glStencilMask(0xff);
      break;
    case MARK_PART:  // only where the fragment passes the depth test, too
      use(GL_ALWAYS, kPartBit, 0, kPartBit);
      break;
    case MARK_LAYER:
      use(GL_ALWAYS, kLayerBit, 0, kLayerBit);
      break;
    case OUTSIDE_LAYER:
      use(GL_EQUAL, 0, kLayerBit, 0);
      break;
    case OUTSIDE_LAYER_AND_PARTS:
      use(GL_EQUAL, 0, kLayerBit | kPartBit, 0);
      break;
    case INSIDE_LAYER:
      use(GL_EQUAL, kLayerBit, kLayerBit, 0);
      break;
    case ON_PARTS_OUTSIDE_LAYER:
      use(GL_EQUAL, kPartBit, kLayerBit | kPartBit, 0);
      break;
  }
}

void GLStencilElement::clearLayerBit() {
  GLint written = 0xff;
  glGetIntegerv(GL_STENCIL_WRITEMASK, &written);
  glStencilMask(kLayerBit);
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
  glStencilMask(static_cast<GLuint>(written));
}

namespace {
void clearStencil(void*, SoGLRenderAction*) {
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
}
}  // namespace

void GLStencilElement::clearEachFrame(SoGLRenderAction* action) {
  // The flag lives in the bottom element, which lasts as long as the action's state.
  const auto* element = static_cast<const GLStencilElement*>(action->getState()->getConstElement(classStackIndex));
  while (element->getNextInStack()) element = static_cast<const GLStencilElement*>(element->getNextInStack());
  if (element->clearedEachFrame_) return;
  const_cast<GLStencilElement*>(element)->clearedEachFrame_ = true;
  clearStencil(nullptr, action);  // this frame: nothing has used the stencil yet
  action->addPreRenderCallback(clearStencil, nullptr);
}
