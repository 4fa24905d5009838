// A capsule's twelve fields read from a scene into the parameters and back, a volume made from
// them, and a bad field refused with the node's name.
#include <Inventor/SbBox.h>
#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "nodes/body/CapsuleVolume.h"
#include "sim/collision/Capsule.h"
#include "sim/collision/CollisionVolume.h"
#include "support/SceneTestSupport.h"

using namespace figment::test;

namespace {

class CapsuleVolumeTest : public testing::Test {
 protected:
  void SetUp() override { initCoin(); }
};

TEST_F(CapsuleVolumeTest, FieldsAreTheParametersInThePapersOrder) {
  SceneRoot root = readString(
      "#Inventor V2.1 ascii\nSeparator { DEF Arm CapsuleVolume { part \"forearmL\" r1 0.5 r2 0.25 tx 0.1 tz -0.1 "
      "x 0.1 y 0.3 z 0.12 ox 0.2 oy 1.1 oz 0.05 theta 0.5 phi 0.25 } }\n");
  ASSERT_TRUE(root);
  auto* capsule = find<CapsuleVolume>(root.get(), "Arm");
  ASSERT_NE(capsule, nullptr);
  const std::array<double, 12> expected = {0.5, 0.25, 0.1, -0.1, 0.1, 0.3, 0.12, 0.2, 1.1, 0.05, 0.5, 0.25};
  const std::array<double, 12> values = capsule->parameters().values();
  for (int i = 0; i < 12; ++i) EXPECT_FLOAT_EQ(float(values[i]), float(expected[i])) << i;
  figment::CapsuleParameters moved = capsule->parameters();
  moved.oy = 0.9;
  capsule->setParameters(moved);
  EXPECT_FLOAT_EQ(capsule->oy.getValue(), 0.9f);
  EXPECT_EQ(capsule->label(), "CapsuleVolume 'Arm'");
}

TEST_F(CapsuleVolumeTest, MakesTheVolumeItsFieldsDescribe) {
  SceneRoot root = readString("#Inventor V2.1 ascii\nSeparator { CapsuleVolume { oy 1 } }\n");
  ASSERT_TRUE(root);
  const auto volume = find<CapsuleVolume>(root.get())->makeVolume({});
  ASSERT_NE(volume, nullptr);
  EXPECT_TRUE(volume->contains(figment::Vec3(0, 1, 0)));
  EXPECT_FALSE(volume->contains(figment::Vec3(0, 0, 0)));  // half a metre below its bottom end
}

TEST_F(CapsuleVolumeTest, ABadFieldIsRefusedNamingTheNode) {
  SceneRoot root = readString("#Inventor V2.1 ascii\nSeparator { DEF Arm CapsuleVolume { x -0.1 } }\n");
  ASSERT_TRUE(root);
  try {
    find<CapsuleVolume>(root.get())->makeVolume({});
    FAIL() << "a negative x was accepted";
  } catch (const std::invalid_argument& e) {
    const std::string text = e.what();
    EXPECT_EQ(text.rfind("CapsuleVolume 'Arm': ", 0), 0u) << text;
    EXPECT_NE(text.find("x = -0.1"), std::string::npos) << text;
  }
}

TEST_F(CapsuleVolumeTest, ItsWireframeBoundsTheCapsule) {
  SceneRoot root = readString("#Inventor V2.1 ascii\nSeparator { CapsuleVolume { y 2 } }\n");
  ASSERT_TRUE(root);
  SoGetBoundingBoxAction box{SbViewportRegion(100, 100)};
  box.apply(root.get());
  const SbBox3f bounds = box.getBoundingBox();
  ASSERT_FALSE(bounds.isEmpty());
  float dx, dy, dz;
  bounds.getSize(dx, dy, dz);
  // The wireframe's rings are polygons inscribed in the surface: within 2 % of the capsule's
  // height (the unit height scaled by y) and diameter, never beyond them.
  EXPECT_LE(dy, 2.0f + 1e-4f);
  EXPECT_GE(dy, 0.98f * 2.0f);
  EXPECT_LE(dx, 1.0f + 1e-4f);
  EXPECT_GE(dx, 0.98f);
}

}  // namespace
