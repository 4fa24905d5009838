#include "nodes/render/StencilRuleElement.h"

#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/misc/SoState.h>

#include "nodes/NodeSource.h"

FIGMENT_ELEMENT_SOURCE(StencilRuleElement)

StencilRuleElement::~StencilRuleElement() = default;

void StencilRuleElement::init(SoState* state) {
  inherited::init(state);
  data = 1;
}

void StencilRuleElement::set(SoState* state, bool ruleDecides) {
  inherited::set(classStackIndex, state, ruleDecides ? 1 : 0);
}

bool StencilRuleElement::get(SoState* state) {
  return state->isElementEnabled(classStackIndex) && inherited::get(classStackIndex, state) != 0;
}

namespace figment {
namespace {
// Runs once per frame, in the state the whole traversal inherits.
void ruleOff(void*, SoGLRenderAction* action) {
  StencilRuleElement::set(action->getState(), false);
}
}  // namespace

void keepStencilFields(SoGLRenderAction& action, bool keep) {
  if (keep)
    action.addPreRenderCallback(ruleOff, nullptr);
  else
    action.removePreRenderCallback(ruleOff, nullptr);
}
}  // namespace figment
