// HumanBody: MakeHuman's body made when read, to its typed measurements; a MeshFile and a
// collision body; a set out of reach is a read error naming the node and the measurement.
// Skipped when MakeHuman's data is absent (scripts/setup.sh fetches it).

#include <Inventor/misc/SoChildList.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include "io/MakeHumanFiles.h"
#include "nodes/body/HumanBody.h"
#include "sim/body/BodyMeasurements.h"
#include "sim/collision/MeshCollider.h"
#include "sim/collision/MovingMeshCollider.h"
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

namespace {

// The highest drawn point out beyond the left shoulder (x > 0.25 m).
double highestLeftOfTheShoulder(const HumanBody& body) {
  double top = 0.0;
  for (int i = 0; i < body.point.getNum(); ++i)
    if (body.point[i][0] > 0.25f) top = std::max(top, double(body.point[i][1]));
  return top;
}

// How far out to the left the body reaches (the left fingertips).
double farthestLeft(const HumanBody& body) {
  double out = 0.0;
  for (int i = 0; i < body.point.getNum(); ++i) out = std::max(out, double(body.point[i][0]));
  return out;
}

}  // namespace

TEST_F(HumanBodyTest, APoseTurnsTheDrawnBodyAndItsColliderMovesIntoIt) {
  SceneRoot root = read("stature 1.68 pose ARM_RAISED");
  ASSERT_TRUE(root);
  auto* body = find<HumanBody>(root.get());
  EXPECT_GT(highestLeftOfTheShoulder(*body), 1.6);  // the left hand raised above the shoulder
  double head = 0.0;
  for (int i = 0; i < body->point.getNum(); ++i)
    if (std::abs(body->point[i][0]) < 0.1f) head = std::max(head, double(body->point[i][1]));
  EXPECT_NEAR(head, 1.68, 0.005);  // the head did not move
  auto moving = std::dynamic_pointer_cast<const figment::MovingMeshCollider>(body->bodyCollider());
  ASSERT_NE(moving, nullptr);
  EXPECT_GT(moving->duration(), 1.0);  // over a metre of the hand's travel at 0.25 m/s
  moving->advanceTo(0.0);              // the drape's start: the rest body
  figment::Contact c;
  EXPECT_FALSE(moving->current().contact(figment::Vec3(0.3, 1.62, 0.0), 0.0, 0.1, c));
  body->pose = HumanBody::A_POSE;
  EXPECT_LT(highestLeftOfTheShoulder(*body), 1.3);  // the rest pose: arms 45 degrees down
  EXPECT_EQ(std::dynamic_pointer_cast<const figment::MovingMeshCollider>(body->bodyCollider()), nullptr);
}

// What a posed body's fit is measured on: its rest pose, numbered as the posed skin (the
// same triangles, the same vertex count), the body as made to its measurements; standing,
// the skin itself.
TEST_F(HumanBodyTest, APosedBodyKeepsItsRestSurface) {
  SceneRoot root = read("stature 1.68 hipGirth 0.96 pose SITTING");
  ASSERT_TRUE(root);
  auto* body = find<HumanBody>(root.get());
  const figment::TriangleMesh rest = body->restSurface(), posed = body->collisionSurface();
  ASSERT_EQ(rest.vertices.size(), posed.vertices.size());
  EXPECT_EQ(rest.triangles, posed.triangles);
  EXPECT_NE(rest.vertices, posed.vertices);
  EXPECT_NEAR(figment::measureBody(rest).hipGirth, 0.96, 0.005);  // the made body, standing
  body->pose = HumanBody::A_POSE;
  EXPECT_EQ(body->restSurface().vertices, body->collisionSurface().vertices);
}

TEST_F(HumanBodyTest, AJointsRotationFollowsThePreset) {
  SceneRoot root = read("rotatedJoints \"upperarm01.L\" rotations 0 0 1 0.8");
  ASSERT_TRUE(root);
  auto* body = find<HumanBody>(root.get());
  const double raised = farthestLeft(*body);
  body->rotations.set1Value(0, SbRotation(SbVec3f(0, 0, 1), -0.2f));  // down, about -z
  const double lowered = farthestLeft(*body);
  body->rotatedJoints.enableNotify(FALSE);  // both lists at once: never one name short
  body->rotatedJoints.setNum(0);
  body->rotatedJoints.enableNotify(TRUE);
  body->rotations.setNum(0);
  const double rest = farthestLeft(*body);
  EXPECT_GT(raised, rest + 0.1);  // the left arm turned up and out to level
  EXPECT_LT(lowered, rest - 0.02);
  body->rotatedJoints.enableNotify(FALSE);
  body->rotatedJoints.set1Value(0, "upperarm01.L");
  body->rotatedJoints.enableNotify(TRUE);
  body->rotations.set1Value(0, SbRotation(SbVec3f(0, 0, 1), 0.8f));
  body->poseTime = 2.0f;
  auto moving = std::dynamic_pointer_cast<const figment::MovingMeshCollider>(body->bodyCollider());
  ASSERT_NE(moving, nullptr);
  EXPECT_EQ(moving->duration(), 2.0);
}

TEST_F(HumanBodyTest, BadPoseFieldsAreReadErrorsNamingThem) {
  for (const auto& [fields, message] : std::vector<std::pair<std::string, std::string>>{
           {"rotatedJoints \"elbow.L\" rotations 1 0 0 1", "no bone 'elbow.L'"},
           {"rotatedJoints [ \"lowerleg01.L\", \"lowerleg01.R\" ] rotations 1 0 0 1", "rotatedJoints has 2 names"},
           {"skinTone 11", "skinTone 11"},
           {"poseTime -1", "poseTime"}}) {
    CapturedErrors errors;
    SceneRoot root = read(fields);
    EXPECT_FALSE(root) << fields;
    EXPECT_NE(errors.all().find("HumanBody 'Made': "), std::string::npos) << errors.all();
    EXPECT_NE(errors.all().find(message), std::string::npos) << errors.all();
  }
}

TEST_F(HumanBodyTest, ASkinToneIsTheDrawnBodysMaterial) {
  SceneRoot root = read("skinTone 6");
  ASSERT_TRUE(root);
  auto* body = find<HumanBody>(root.get());
  auto* mesh = static_cast<SoSeparator*>((*body->getChildren())[0]);
  ASSERT_TRUE(mesh->getChild(0)->isOfType(SoMaterial::getClassTypeId()));
  const SbColor colour = static_cast<SoMaterial*>(mesh->getChild(0))->diffuseColor[0];
  EXPECT_EQ(colour, HumanBody::monkSkinTone(6));
  EXPECT_NEAR(colour[0] * 255.0f, 0xa0, 1e-3);  // Monk 6, #a07e56
  EXPECT_NEAR(colour[1] * 255.0f, 0x7e, 1e-3);
  EXPECT_NEAR(colour[2] * 255.0f, 0x56, 1e-3);
  body->skinTone = 0;  // the scene's Material again
  EXPECT_FALSE(mesh->getChild(0)->isOfType(SoMaterial::getClassTypeId()));
}
