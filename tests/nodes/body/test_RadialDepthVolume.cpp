// A radial depth volume's fields into its parameters: the axis normalised, the reference made
// perpendicular to it, the coefficients cut into sections; each bad field refused naming the
// node and the field.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "nodes/body/RadialDepthVolume.h"
#include "sim/collision/CollisionVolume.h"
#include "sim/collision/RadialDepth.h"
#include "support/Refusal.h"
#include "support/SceneTestSupport.h"

using namespace figment::test;

namespace {

class RadialDepthVolumeTest : public testing::Test {
 protected:
  void SetUp() override { initCoin(); }
  static std::string refusal(const char* fields) {
    SceneRoot root =
        readString(std::string("#Inventor V2.1 ascii\nSeparator { DEF Thigh RadialDepthVolume { ") + fields + " } }\n");
    EXPECT_TRUE(root);
    return figment::test::refusal([&] { find<RadialDepthVolume>(root.get())->parameters(); });
  }
};

TEST_F(RadialDepthVolumeTest, FieldsBecomeAnAxisAReferenceAndSections) {
  SceneRoot root = readString(
      "#Inventor V2.1 ascii\nSeparator { RadialDepthVolume { base 0 1 0 direction 0 2 0 reference 1 1 0 "
      "length 0.5 harmonics 1 coefficients [ 0.1 0 0  0.12 0.01 0  0.1 0 0 ] } }\n");
  ASSERT_TRUE(root);
  const RadialDepthVolume* node = find<RadialDepthVolume>(root.get());
  const figment::RadialDepthParameters p = node->parameters();
  EXPECT_TRUE(p.direction.isApprox(figment::Vec3::UnitY()));
  EXPECT_TRUE(p.reference.isApprox(figment::Vec3::UnitX()));  // (1 1 0) less its part along y
  ASSERT_EQ(p.coefficients.size(), 3u);
  EXPECT_DOUBLE_EQ(p.coefficients[1][1], double(0.01f));
  const auto volume = node->makeVolume({});
  EXPECT_TRUE(volume->contains(figment::Vec3(0, 1.25, 0)));  // on the axis, halfway up
  EXPECT_FALSE(volume->contains(figment::Vec3(0.3, 1.25, 0)));
}

TEST_F(RadialDepthVolumeTest, RefusesEachBadFieldNamingIt) {
  EXPECT_EQ(refusal("direction 0 0 0 coefficients [ 0.1 0.1 ]"),
            "RadialDepthVolume 'Thigh': direction = 0 0 0 is not an axis");
  EXPECT_EQ(refusal("direction 0 1 0 reference 0 2 0 coefficients [ 0.1 0.1 ]"),
            "RadialDepthVolume 'Thigh': reference is parallel to direction");
  EXPECT_EQ(refusal("harmonics -1 coefficients [ 0.1 0.1 ]"), "RadialDepthVolume 'Thigh': harmonics = -1 must be >= 0");
  EXPECT_EQ(
      refusal("harmonics 1 coefficients [ 0.1 0 0 0.1 ]"),
      "RadialDepthVolume 'Thigh': coefficients has 4 values, not a multiple (>= 2 sections) of 2 harmonics + 1 = 3");
  EXPECT_EQ(
      refusal("harmonics 0 coefficients [ 0.1 ]"),
      "RadialDepthVolume 'Thigh': coefficients has 1 values, not a multiple (>= 2 sections) of 2 harmonics + 1 = 1");
}

}  // namespace
