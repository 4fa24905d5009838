#include "guard/GuardedInput.h"

#include <Inventor/SbName.h>
#include <Inventor/errors/SoReadError.h>

namespace figment::guard {

SbBool GuardedInput::read(SbName& name, SbBool validIdent) {
  if (reading_) return ReferenceHoldingInput::read(name, validIdent);
  reading_ = true;
  const SbBool ok = ReferenceHoldingInput::read(name, validIdent);
  reading_ = false;
  if (!ok) return ok;
  const std::string problem = declarations_.seeName(name);
  if (problem.empty()) return ok;
  SoReadError::post(this, "%s", problem.c_str());
  if (refusal_.empty()) refusal_ = problem;
  return FALSE;
}

SbBool GuardedInput::read(char& c) {
  if (reading_) return ReferenceHoldingInput::read(c);
  reading_ = true;
  const SbBool ok = ReferenceHoldingInput::read(c);
  reading_ = false;
  if (ok) declarations_.seeChar(c);
  return ok;
}

}  // namespace figment::guard
