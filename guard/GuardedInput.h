#pragma once
// The SoInput the guard reads scenes through (SceneFile.h): it holds what DEF names until the
// read is over (ReferenceHoldingInput.h), and sees every name and character Coin's reader
// reads, in the scene and in each file it includes (File, VRMLInline and EXTERNPROTO push their
// files onto this input), so that a field declaration Coin would add to a whole class is
// refused before Coin adds it (FieldDeclarations.h).

#include "guard/FieldDeclarations.h"
#include "guard/ReferenceHoldingInput.h"

namespace figment::guard {

class GuardedInput : public ReferenceHoldingInput {
 public:
  using ReferenceHoldingInput::read;
  // A name refused posts its one line as a read error, and reads as a failure.
  SbBool read(SbName& name, SbBool validIdent = FALSE) override;
  SbBool read(char& c) override;

  // The first line refused, as posted: "" when none was. Coin reads on past a file a File or
  // VRMLInline includes that failed to read (its node is left empty), so a refusal there does
  // not fail the read by itself: the reader asks.
  const std::string& refusal() const { return refusal_; }

 private:
  FieldDeclarations declarations_;
  std::string refusal_;
  bool reading_ = false;  // inside one of the reads above: what it reads itself is not seen
};

}  // namespace figment::guard
