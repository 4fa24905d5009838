#include "nodes/GLStencilElement.h"

#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/misc/SoState.h>

#include <GL/gl.h>

SO_ELEMENT_SOURCE(GLStencilElement);

// The mark a StencilSeparator writes and a masked ClothingLayer avoids.
static constexpr GLint kMark = 1;

void GLStencilElement::initClass() {
  if (getClassTypeId() != SoType::badType()) return;
  SO_ELEMENT_INIT_CLASS(GLStencilElement, inherited);
  SO_ENABLE(SoGLRenderAction, GLStencilElement);
}

GLStencilElement::~GLStencilElement() = default;

void GLStencilElement::init(SoState* state) {
  inherited::init(state);
  mode_ = OFF;
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
  switch (mode_) {
    case OFF:
      glDisable(GL_STENCIL_TEST);
      break;
    case WRITE:  // mark every pixel drawn (that passes the depth test)
      glEnable(GL_STENCIL_TEST);
      glStencilFunc(GL_ALWAYS, kMark, 0xff);
      glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
      break;
    case MASK:  // draw only where nothing is marked
      glEnable(GL_STENCIL_TEST);
      glStencilFunc(GL_NOTEQUAL, kMark, 0xff);
      glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
      break;
  }
}

namespace figment {
namespace {
void clearStencil(void*, SoGLRenderAction*) {
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
}
}  // namespace

void clearStencilEachFrame(SoGLRenderAction& action) { action.addPreRenderCallback(clearStencil, nullptr); }
}  // namespace figment
