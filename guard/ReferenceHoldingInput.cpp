#include "guard/ReferenceHoldingInput.h"

#include <Inventor/misc/SoBase.h>

namespace figment::guard {

ReferenceHoldingInput::~ReferenceHoldingInput() {
  release();
}

void ReferenceHoldingInput::addReference(const SbName& name, SoBase* base, SbBool addToGlobalDict) {
  SoInput::addReference(name, base, addToGlobalDict);
  if (!base) return;
  base->ref();
  held_.push_back(base);
}

void ReferenceHoldingInput::release() {
  // Taken out first: an object destroyed here may unref others (an engine its field).
  std::vector<SoBase*> held;
  held.swap(held_);
  for (SoBase* base : held) base->unref();
}

}  // namespace figment::guard
