#pragma once
// An SoInput that holds a reference to every object the text names with DEF until the read
// is over.
//
// Coin's reader keeps each DEF name's object in the input's reference table as a bare
// pointer, and an object is destroyed when its reference count falls to zero, even while
// the read goes on. An engine DEFined in place in a field connection has no reference but
// the connection; when the field cannot take the engine's output (a ClothEngine's SoMFVec3f
// positions into a Coordinate4's SoMFVec4f point), the failed connection destroys the
// engine, and a later `USE Name.output` read freed memory (found by tests/fuzz/fuzz_scene;
// figment-view aborted; a plain Calculator does the same). Held, the object lives until
// release(), and is destroyed there if nothing else took it.

#include <Inventor/SoInput.h>

#include <vector>

namespace figment::guard {

class ReferenceHoldingInput : public SoInput {
 public:
  ReferenceHoldingInput() = default;
  ReferenceHoldingInput(const ReferenceHoldingInput&) = delete;
  ReferenceHoldingInput& operator=(const ReferenceHoldingInput&) = delete;
  ~ReferenceHoldingInput() override;

  void addReference(const SbName& name, SoBase* base, SbBool addToGlobalDict = TRUE) override;

  // Lets go of every object held; call after taking a reference to the scene read.
  void release();

 private:
  std::vector<SoBase*> held_;
};

}  // namespace figment::guard
