// What a study's garments collide with, by name: nothing chosen for "scene", the Mannequin's
// body for "exact", a copy of the Mannequin with a volumes file's children; and each choice
// the scene cannot serve refused in one line naming it.
#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/nodes/SoFile.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include <string>

#include "bench/BodyChoice.h"
#include "nodes/Init.h"
#include "nodes/body/Mannequin.h"
#include "support/SceneTestSupport.h"
#include "support/TPoseSkeleton.h"
#include "support/TempDir.h"

using namespace figment;

namespace {

SoSeparator* readScene(const std::string& text) {
  figment::init();
  SoInput in;
  in.setBuffer(text.data(), text.size());
  SoSeparator* root = SoDB::readAll(&in);
  if (root) root->ref();
  return root;
}

TEST(BodyChoice, SceneExactAndAVolumesFile) {
  const test::TempDir dir;
  const std::string cube = dir.file("cube.obj", test::cubeObj());
  SoSeparator* root = readScene(std::string("#Inventor V2.1 ascii\nSeparator { DEF Model Mannequin {\n") +
                                "  body DEF Skin MeshFile { fileName \"" + cube + "\" }  height 1.8\n" +
                                test::kTPoseJoints + test::kForearmCapsule + "} }\n");
  ASSERT_NE(root, nullptr);
  std::string error;
  EXPECT_EQ(bench::bodyFor("scene", root, error), nullptr);
  EXPECT_EQ(error, "");
  EXPECT_EQ(bench::bodyFor("exact", root, error), SoNode::getByName("Skin"));
  const std::string volumes = dir.file("volumes.iv", "#Inventor V2.1 ascii\nCapsuleVolume { part \"head\" }\n");
  SoNode* other = bench::bodyFor(volumes, root, error);
  ASSERT_NE(other, nullptr) << error;
  other->ref();
  ASSERT_TRUE(other->isOfType(Mannequin::getClassTypeId()));
  EXPECT_NE(other, SoNode::getByName("Model"));  // a copy, the scene's own untouched
  EXPECT_FLOAT_EQ(static_cast<Mannequin*>(other)->height.getValue(), 1.8f);
  // The file in place of the scene's volumes (its skeleton and capsule).
  ASSERT_EQ(static_cast<Mannequin*>(other)->getNumChildren(), 1);
  EXPECT_TRUE(static_cast<Mannequin*>(other)->getChild(0)->isOfType(SoFile::getClassTypeId()));
  other->unref();
  root->unref();
}

TEST(BodyChoice, AChoiceTheSceneCannotServeIsOneLine) {
  SoSeparator* root = readScene("#Inventor V2.1 ascii\nSeparator { Cube { } }\n");
  ASSERT_NE(root, nullptr);
  std::string error;
  EXPECT_EQ(bench::bodyFor("exact", root, error), nullptr);
  EXPECT_EQ(error, "--body exact needs a scene with one Mannequin");
  root->unref();
  const test::TempDir dir;
  const std::string cube = dir.file("cube.obj", test::cubeObj());
  root = readScene(std::string("#Inventor V2.1 ascii\nSeparator { Mannequin {\n  body MeshFile { fileName \"") + cube +
                   "\" }\n" + test::kTPoseJoints + test::kForearmCapsule + "} }\n");
  ASSERT_NE(root, nullptr);
  const std::string empty = dir.file("empty.iv", "#Inventor V2.1 ascii\n");
  EXPECT_EQ(bench::bodyFor(empty, root, error), nullptr);
  EXPECT_EQ(error, "--body " + empty + ": no volumes read from it");
  root->unref();
}

}  // namespace
