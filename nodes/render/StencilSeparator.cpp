#include "nodes/render/StencilSeparator.h"

#include "nodes/render/GLStencilElement.h"

#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/misc/SoState.h>

SO_NODE_SOURCE(StencilSeparator);

void StencilSeparator::initClass() {
  if (classTypeId != SoType::badType()) return;
  GLStencilElement::initClass();
  SO_NODE_INIT_CLASS(StencilSeparator, SoSeparator, "Separator");
}

StencilSeparator::StencilSeparator() {
  SO_NODE_CONSTRUCTOR(StencilSeparator);
  SO_NODE_ADD_FIELD(writeStencil, (FALSE));
}

StencilSeparator::~StencilSeparator() = default;

// The mode is set in a pushed state around the separator's own traversal, so it holds
// for the children and the pop restores the GL state below.
void StencilSeparator::renderMarking(SoGLRenderAction* action, bool inPath) {
  SoState* state = action->getState();
  state->push();
  if (writeStencil.getValue()) GLStencilElement::set(state, GLStencilElement::MARK_PART);
  if (inPath) inherited::GLRenderInPath(action);
  else inherited::GLRenderBelowPath(action);
  state->pop();
}

void StencilSeparator::GLRenderBelowPath(SoGLRenderAction* action) { renderMarking(action, false); }

void StencilSeparator::GLRenderInPath(SoGLRenderAction* action) { renderMarking(action, true); }
