// The input scenes are read through refuses a field declaration Coin would add to a whole class,
// as Coin reads it, in the scene and in the files it includes; the class is left as it was.

#include <Inventor/SoDB.h>
#include <Inventor/lists/SoFieldList.h>
#include <Inventor/nodes/SoCube.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include <string>

#include "guard/GuardedInput.h"
#include "support/SceneTestSupport.h"

using figment::guard::GuardedInput;

namespace {

struct Read {
  bool read = false;
  std::string refusal;
};

Read readThroughGuard(const std::string& text) {
  figment::test::initCoin();
  figment::test::CapturedErrors quiet;
  GuardedInput in;
  in.setBuffer(text.data(), text.size());
  SoSeparator* root = SoDB::readAll(&in);
  Read out{root != nullptr, in.refusal()};
  if (root) {
    root->ref();
    root->unref();
  }
  in.release();
  return out;
}

int cubeFields() {
  SoCube* cube = new SoCube;
  cube->ref();
  SoFieldList fields;
  const int n = cube->getFields(fields);
  cube->unref();
  return n;
}

}  // namespace

TEST(GuardedInput, RefusesAFieldDeclarationTheClassDoesNotMatch) {
  figment::test::initCoin();
  const int before = cubeFields();
  const Read wobble = readThroughGuard(
      "#Inventor V2.1 ascii\nSeparator {\n  Cube { fields [ SFFloat width, SFFloat "
      "wobble ] width 2 }\n  Cube { }\n}\n");
  EXPECT_FALSE(wobble.read);
  EXPECT_EQ(wobble.refusal, "Cube: fields [ SFFloat wobble ] declares a field Cube does not have");
  EXPECT_EQ(cubeFields(), before) << "Coin added the declared field to every Cube";
  const Read mistyped =
      readThroughGuard("#Inventor V2.1 ascii\nDEF Head CapsuleVolume { fields [ SFString part, SFInt32 r1 ] r1 1 }\n");
  EXPECT_EQ(mistyped.refusal,
            "CapsuleVolume 'Head': fields [ SFInt32 r1 ] declares r1 an SFInt32, but it is an SFFloat");
}

TEST(GuardedInput, ReadsWhatCoinWritesForFigmentsNodes) {
  const Read volume = readThroughGuard(
      "#Inventor V2.1 ascii\nGroup {\n  CapsuleVolume {\n    fields [ SFString part, SFFloat r1, SFFloat r2 ]\n"
      "    part \"head\" r1 0.5\n  }\n  CapsuleVolume { fields [ SFString part ] part \"neck\" }\n}\n");
  EXPECT_TRUE(volume.read);
  EXPECT_EQ(volume.refusal, "");
}
