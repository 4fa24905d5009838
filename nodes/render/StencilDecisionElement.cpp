#include "nodes/render/StencilDecisionElement.h"

#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/misc/SoState.h>

#include "nodes/NodeSource.h"

FIGMENT_ELEMENT_SOURCE(StencilDecisionElement)

bool StencilDecisionElement::Key::operator==(const Key& other) const {
  return root == other.root && rootId == other.rootId && affine == other.affine && projection == other.projection &&
         viewport == other.viewport;
}

StencilDecisionElement::~StencilDecisionElement() = default;

void StencilDecisionElement::init(SoState* state) {
  inherited::init(state);
  decided_ = false;
}

const figment::StencilDecision& StencilDecisionElement::decisionFor(
    SoState* state, const Key& key, const std::function<figment::StencilDecision()>& decide) {
  const auto* kept = static_cast<const StencilDecisionElement*>(state->getConstElement(classStackIndex));
  if (!kept->decided_ || !(kept->key_ == key)) {
    kept->decision_ = decide();
    kept->key_ = key;
    kept->decided_ = true;
  }
  return kept->decision_;
}

// A cache never decides whether a render cache is valid: every element matches.
SbBool StencilDecisionElement::matches(const SoElement*) const {
  return TRUE;
}

SoElement* StencilDecisionElement::copyMatchInfo() const {
  return static_cast<SoElement*>(getTypeId().createInstance());
}
