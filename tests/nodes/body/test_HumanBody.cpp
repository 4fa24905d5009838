// HumanBody: MakeHuman's body made when read, to its typed measurements; a MeshFile and a
// collision body; a set out of reach is a read error naming the node and the measurement.
// Skipped when MakeHuman's data is absent (scripts/setup.sh fetches it).

#include <gtest/gtest.h>

#include "io/MakeHumanFiles.h"
#include "nodes/body/HumanBody.h"
#include "sim/body/BodyMeasurements.h"
#include "sim/collision/MeshCollider.h"
#include "support/SceneTestSupport.h"

using namespace figment::test;

namespace {

class HumanBodyTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (figment::findMakeHumanData().empty()) GTEST_SKIP() << "MakeHuman's data not found";
    initCoin();
  }
  static SceneRoot read(const std::string& fields) {
    return readString("#Inventor V2.1 ascii\nSeparator { DEF Made HumanBody { " + fields + " } }\n");
  }
};

}  // namespace

TEST_F(HumanBodyTest, IsMadeToItsTypedMeasurementsWhenRead) {
  SceneRoot root = read("stature 1.68 bustGirth 0.88 waistGirth 0.72 hipGirth 0.96");
  ASSERT_TRUE(root);
  auto* body = find<HumanBody>(root.get());
  ASSERT_NE(body, nullptr);
  EXPECT_EQ(body->point.getNum(), 13380);  // the skin's vertices, drawn and offered
  const figment::BodyMeasurements m = figment::measureBody(body->collisionSurface());
  EXPECT_NEAR(m.stature, 1.68, 0.005);
  EXPECT_NEAR(m.bustGirth, 0.88, 0.005);
  EXPECT_NEAR(m.waistGirth, 0.72, 0.005);
  EXPECT_NEAR(m.hipGirth, 0.96, 0.005);
  // a body wherever a MeshFile is: its triangles collide, exactly
  EXPECT_TRUE(body->isOfType(MeshFile::getClassTypeId()));
  ASSERT_NE(figment::asCollisionBody(body), nullptr);
  EXPECT_NE(body->bodyCollider(), nullptr);
}

TEST_F(HumanBodyTest, AFieldChangeMakesTheBodyAgain) {
  SceneRoot root = read("gender 1");
  ASSERT_TRUE(root);
  auto* body = find<HumanBody>(root.get());
  const double male = figment::measureBody(body->collisionSurface()).stature;
  body->gender = 0.0f;
  const double female = figment::measureBody(body->collisionSurface()).stature;
  EXPECT_GT(male - female, 0.05);  // MakeHuman's average man is taller than its average woman
}

TEST_F(HumanBodyTest, ASetOutOfReachIsAReadErrorNamingTheMeasurement) {
  CapturedErrors errors;
  SceneRoot root = read("waistGirth 0.9 hipGirth 0.5");
  EXPECT_FALSE(root);
  EXPECT_NE(errors.all().find("HumanBody 'Made': hip_girth 0.500 m is out of reach"), std::string::npos)
      << errors.all();
}

TEST_F(HumanBodyTest, AFileNameIsRefused) {
  CapturedErrors errors;
  SceneRoot root = read("fileName \"human.zae\"");
  EXPECT_FALSE(root);
  EXPECT_NE(errors.all().find("leave fileName empty"), std::string::npos) << errors.all();
}
