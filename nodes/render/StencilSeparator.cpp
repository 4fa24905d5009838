#include "nodes/render/StencilSeparator.h"

#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/elements/SoCacheElement.h>
#include <Inventor/misc/SoState.h>

#include "nodes/NodeSource.h"
#include "nodes/render/GLStencilElement.h"
#include "nodes/render/StencilDecisionElement.h"
#include "nodes/render/StencilRule.h"
#include "nodes/render/StencilRuleElement.h"

FIGMENT_NODE_SOURCE_AFTER(StencilSeparator, SoSeparator, "Separator", initStencilElements)

StencilSeparator::StencilSeparator() {
  SO_NODE_CONSTRUCTOR(StencilSeparator);
  SO_NODE_ADD_FIELD(writeStencil, (FALSE));
  SO_NODE_ADD_FIELD(stencilRule, (TRUE));
}

StencilSeparator::~StencilSeparator() = default;

bool StencilSeparator::writesStencil(SoGLRenderAction* action) {
  SoState* state = action->getState();
  if (!stencilRule.getValue() || !StencilRuleElement::get(state)) return writeStencil.getValue();
  // The rule's answer depends on the view: no render cache above may keep it.
  SoCacheElement::invalidate(state);
  return figment::decideStencil(action).writes(this);
}

// The mode is set in a pushed state around the separator's own traversal, so it holds
// for the children and the pop restores the GL state below.
void StencilSeparator::renderMarking(SoGLRenderAction* action, bool inPath) {
  SoState* state = action->getState();
  GLStencilElement::clearEachFrame(action);
  const bool writes = writesStencil(action);
  state->push();
  if (writes) GLStencilElement::set(state, GLStencilElement::MARK_PART);
  if (inPath)
    inherited::GLRenderInPath(action);
  else
    inherited::GLRenderBelowPath(action);
  state->pop();
}

void StencilSeparator::GLRenderBelowPath(SoGLRenderAction* action) {
  renderMarking(action, false);
}

void StencilSeparator::GLRenderInPath(SoGLRenderAction* action) {
  renderMarking(action, true);
}
