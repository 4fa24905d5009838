// The input figment-view reads scenes with holds every object a DEF names until the read is
// over: Coin's own reference table holds bare pointers, and an engine DEFined in a field
// connection that failed was destroyed under a later USE of its name (found by fuzz_scene).
#include <Inventor/SoDB.h>
#include <Inventor/nodes/SoCube.h>
#include <gtest/gtest.h>

#include "guard/ReferenceHoldingInput.h"

using figment::guard::ReferenceHoldingInput;

TEST(ReferenceHoldingInput, HoldsWhatADefNamesUntilReleased) {
  SoDB::init();
  auto* cube = new SoCube;
  cube->ref();
  {
    ReferenceHoldingInput in;
    in.addReference("Box", cube);
    EXPECT_EQ(in.findReference("Box"), cube);
    EXPECT_EQ(cube->getRefCount(), 2);
    in.release();
    EXPECT_EQ(cube->getRefCount(), 1);
    in.addReference("Box", cube);
    EXPECT_EQ(cube->getRefCount(), 2);
  }  // the destructor releases what is still held
  EXPECT_EQ(cube->getRefCount(), 1);
  cube->unref();
}
