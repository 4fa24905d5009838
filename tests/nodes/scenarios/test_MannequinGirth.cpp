// A Mannequin sized with a narrower chest than waist: its posed collider has no rim where
// the lower torso's volume ends inside the upper torso's (sim/body/GirthBlend.h). The rim
// kept the posed dress with height, chest, hips and arm length all set from resting:
// cloth on it was pushed up by the end cap and out by the side in turn.

#include <gtest/gtest.h>

#include <string>

#include "nodes/body/Mannequin.h"
#include "sim/collision/Collider.h"
#include "support/SceneTestSupport.h"
#include "support/TPoseSkeleton.h"

using namespace figment::test;

namespace {

// Two round radial volumes of radius 0.15 m meeting at the chest joint (y = 1.25): the
// lower torso from the waist joint (1.05), the upper torso up to the neck base (1.45) in
// sections 2 cm apart, as figment-fit spaces them.
std::string torsoScene(const std::string& sizing) {
  return std::string("#Inventor V2.1 ascii\nSeparator {\n  DEF Model Mannequin {\n") + sizing + "\n" + kTPoseJoints +
         "    RadialDepthVolume { part \"lowerTorso\"  base 0 1.05 0  direction 0 1 0  reference 1 0 0\n"
         "      length 0.2  harmonics 0  coefficients [ 0.15, 0.15 ] }\n"
         "    RadialDepthVolume { part \"upperTorso\"  base 0 1.25 0  direction 0 1 0  reference 1 0 0\n"
         "      length 0.2  harmonics 0\n"
         "      coefficients [ 0.15, 0.15, 0.15, 0.15, 0.15, 0.15, 0.15, 0.15, 0.15, 0.15, 0.15 ] }\n"
         "  }\n}\n";
}

class MannequinGirth : public ::testing::Test {
 protected:
  void SetUp() override { initCoin(); }
};

}  // namespace

TEST_F(MannequinGirth, ANarrowerChestLeavesNoRimOfTheLowerTorsoStandingOut) {
  SceneRoot root = readString(torsoScene("chest 0.98"));
  ASSERT_TRUE(root);
  const auto* model = find<Mannequin>(root.get(), "Model");
  ASSERT_NE(model, nullptr);
  const auto collider = model->collider();
  // 5 mm out from the torso's side and 5 mm above the joint's plane. Unblended, the upper
  // torso there is 3 mm narrower (0.147 m) than the lower torso's top rim (0.15 m), and the
  // nearest surface is that rim, its normal tilted 45 degrees up; blended, it is the upper
  // torso's side, its normal all but level (0.075 up: the side narrows by 1.5 mm over the
  // 2 cm to the next section).
  figment::Contact contact;
  collider->contact(figment::Vec3(0.155, 1.255, 0.0), 0.01, 0.1, contact);
  EXPECT_LT(std::abs(contact.normal.y()), 0.1) << "normal " << contact.normal.transpose();
  EXPECT_NEAR(contact.distance, 0.155 - 0.1496, 3e-4);
  // Away from the joint the upper torso keeps its own girth: 0.98 x 0.15 m.
  collider->contact(figment::Vec3(0.16, 1.40, 0.0), 0.02, 0.1, contact);
  EXPECT_NEAR(contact.distance, 0.16 - 0.98 * 0.15, 3e-4);
}
