// Mannequin and its volume nodes: .iv round trips, the posed collider, posing moving
// volumes and skin together, drawing only when shown, and bad input named on read.

#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/actions/SoGetPrimitiveCountAction.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "nodes/body/CapsuleVolume.h"
#include "nodes/body/Mannequin.h"
#include "nodes/body/MannequinSkin.h"
#include "nodes/body/RadialDepthVolume.h"
#include "nodes/body/SkeletonJoints.h"
#include "nodes/cloth/ClothEngine.h"
#include "sim/body/Skeleton.h"
#include "sim/collision/Capsule.h"
#include "sim/collision/Collider.h"
#include "sim/collision/RadialDepth.h"
#include "support/SceneTestSupport.h"
#include "support/TPoseSkeleton.h"

using namespace figment::test;

namespace {

const char* kJoints = kTPoseJoints;
const char* kForearm = kForearmCapsule;
// The upper torso as a round radial volume.
const char* kTorso =
    "DEF Torso RadialDepthVolume { part \"upperTorso\"  base 0 1.25 0  direction 0 1 0  reference 1 0 0\n"
    "  length 0.2  harmonics 1  coefficients [ 0.15 0.01 0,  0.14 0 0 ] }\n";

std::string mannequinScene(const std::string& fields,
                           const std::string& children = std::string(kJoints) + kForearm + kTorso) {
  return "#Inventor V2.1 ascii\nSeparator {\n  DEF Model Mannequin {\n" + fields + "\n" + children + "  }\n}\n";
}

class MannequinTest : public ::testing::Test {
 protected:
  void SetUp() override { initCoin(); }
};

bool inContact(const figment::Collider& collider, const figment::Vec3& p, figment::Contact& contact) {
  return collider.contact(p, 0.0, 0.05, contact);
}

}  // namespace

TEST_F(MannequinTest, VolumeFieldsSurviveAWriteAndARead) {
  SceneRoot root = readString(mannequinScene(""));
  ASSERT_TRUE(root);
  SceneRoot again = readString(writeString(root.get()));
  ASSERT_TRUE(again);
  const auto* capsule = find<CapsuleVolume>(again.get(), "Forearm");
  const auto* radial = find<RadialDepthVolume>(again.get(), "Torso");
  ASSERT_TRUE(capsule && radial);
  EXPECT_EQ(capsule->part.getValue(), "forearmL");
  EXPECT_FLOAT_EQ(capsule->y.getValue(), 0.35f);
  EXPECT_FLOAT_EQ(capsule->theta.getValue(), -1.5707963f);
  EXPECT_EQ(radial->coefficients.getNum(), 6);
  EXPECT_FLOAT_EQ(radial->coefficients[1], 0.01f);
  EXPECT_EQ(find<SkeletonJoints>(again.get())->names.getNum(), 25);
  const auto* model = find<Mannequin>(again.get(), "Model");
  EXPECT_EQ(model->volumes().size(), 2u);
  EXPECT_EQ(model->skeleton().parts[model->volumes()[0].part].name, "forearmL");
}

TEST_F(MannequinTest, ItsColliderIsTheVolumes) {
  SceneRoot root = readString(mannequinScene(""));
  ASSERT_TRUE(root);
  const auto collider = find<Mannequin>(root.get(), "Model")->collider();
  figment::Contact c;
  ASSERT_TRUE(inContact(*collider, {0.575, 1.42, 0.0}, c)) << "the forearm capsule's centre";
  EXPECT_NEAR(c.distance, -0.04, 1e-3);
  ASSERT_TRUE(inContact(*collider, {0.575, 1.42, 0.035}, c));
  EXPECT_NEAR(c.surfacePoint.z(), 0.04, 1e-3);
  EXPECT_NEAR(c.normal.z(), 1.0, 1e-3);
  // The torso's radius is 0.15 + 0.01 cos a at its base: 0.16 along +x.
  EXPECT_TRUE(inContact(*collider, {0.155, 1.26, 0.0}, c));
  EXPECT_FALSE(inContact(*collider, {0.0, 1.35, 0.2}, c)) << "in front of the torso";
  EXPECT_GT(c.distance, 0.0);
  EXPECT_LE(c.distance, 0.2 - 0.145 + 1e-3) << "a lower bound of the distance";
}

TEST_F(MannequinTest, TurningTheShoulderCarriesTheForearmVolume) {
  // The left arm turned down by 90 degrees about z at the shoulder (0.2, 1.42, 0): the
  // forearm's centre moves from x = 0.575 to below the shoulder, 0.375 m down.
  SceneRoot root = readString(mannequinScene("rotatedJoints \"shoulderL\"  rotations 0 0 1 -1.5707963"));
  ASSERT_TRUE(root);
  auto* model = find<Mannequin>(root.get(), "Model");
  const auto collider = model->collider();
  figment::Contact c;
  EXPECT_TRUE(inContact(*collider, {0.2, 1.42 - 0.375, 0.0}, c));
  EXPECT_NEAR(c.distance, -0.04, 1e-3);
  EXPECT_FALSE(inContact(*collider, {0.575, 1.42, 0.0}, c)) << "the rest place is empty now";
  EXPECT_TRUE(inContact(*collider, {0.0, 1.3, 0.0}, c)) << "the torso did not move";

  // Setting the field again from code moves it back: the collider is rebuilt.
  model->rotatedJoints.setNum(0);
  model->rotations.setNum(0);
  EXPECT_TRUE(inContact(*model->collider(), {0.575, 1.42, 0.0}, c));
}

TEST_F(MannequinTest, LongerArmsMoveTheForearmOut) {
  SceneRoot root = readString(mannequinScene("armLength 1.2"));
  ASSERT_TRUE(root);
  const auto collider = find<Mannequin>(root.get(), "Model")->collider();
  figment::Contact c;
  // The elbow moves out to 0.2 + 0.25 * 1.2 m and the forearm is 1.2x longer: its
  // capsule (x 0.4 to 0.75 at rest) spans 0.44 to 0.86 m.
  const double elbow = 0.2 + 0.25 * 1.2;
  EXPECT_TRUE(inContact(*collider, {elbow + 1.2 * (0.72 - 0.45), 1.42, 0.0}, c));
  EXPECT_FALSE(inContact(*collider, {0.43, 1.42, 0.0}, c)) << "inside at rest, left behind now";
}

TEST_F(MannequinTest, DrawsAndBoundsItsVolumesOnlyWhenShown) {
  SceneRoot root = readString(mannequinScene(""));
  ASSERT_TRUE(root);
  auto* model = find<Mannequin>(root.get(), "Model");
  SoGetBoundingBoxAction bbox(SbViewportRegion(100, 100));
  bbox.apply(root.get());
  EXPECT_TRUE(bbox.getBoundingBox().isEmpty());
  SoGetPrimitiveCountAction count;
  count.apply(root.get());
  EXPECT_EQ(count.getLineCount(), 0);

  model->showVolumes = TRUE;
  bbox.apply(root.get());
  const SbBox3f box = bbox.getBoundingBox();
  EXPECT_NEAR(box.getMax()[0], 0.75, 0.01) << "the forearm's far end";
  EXPECT_NEAR(box.getMin()[0], -0.14, 0.01) << "the torso's -x side (0.15 - 0.01 cos 180)";
  count.apply(root.get());
  EXPECT_GT(count.getLineCount(), 100);

  // Posed, the wireframe goes with the arm.
  model->rotatedJoints.setValue("shoulderL");
  model->rotations.setValue(SbRotation(SbVec3f(0, 0, 1), -float(std::numbers::pi / 2)));
  bbox.apply(root.get());
  EXPECT_NEAR(bbox.getBoundingBox().getMin()[1], 1.42 - 0.55, 0.01);
  EXPECT_NEAR(bbox.getBoundingBox().getMax()[0], 0.2 + 0.04, 0.01);
}

TEST_F(MannequinTest, AVolumesDrawingFollowsItsFields) {
  // The wireframe is kept between renders: a field change must renew it.
  SceneRoot root = readString(mannequinScene("showVolumes TRUE"));
  ASSERT_TRUE(root);
  SoGetBoundingBoxAction bbox(SbViewportRegion(100, 100));
  bbox.apply(root.get());
  EXPECT_NEAR(bbox.getBoundingBox().getMax()[0], 0.75, 0.01);
  find<CapsuleVolume>(root.get(), "Forearm")->y = 0.45f;  // 5 cm longer at each end
  bbox.apply(root.get());
  EXPECT_NEAR(bbox.getBoundingBox().getMax()[0], 0.80, 0.01);
}

TEST_F(MannequinTest, TheSkinFollowsThePose) {
  TempDir dir;
  // A 4 cm box around the middle of the left forearm (x 0.55-0.6), as the body mesh.
  dir.file("arm.obj",
           "v 0.55 1.40 -0.02\nv 0.6 1.40 -0.02\nv 0.55 1.44 -0.02\nv 0.6 1.44 -0.02\n"
           "v 0.55 1.40 0.02\nv 0.6 1.40 0.02\nv 0.55 1.44 0.02\nv 0.6 1.44 0.02\n"
           "f 1 5 7 3\nf 2 4 8 6\nf 1 2 6 5\nf 3 7 8 4\nf 1 3 4 2\nf 5 6 8 7\n");
  const std::string path =
      dir.file("scene.iv", mannequinScene("body DEF Arm MeshFile { fileName \"arm.obj\" }\n"
                                          "rotatedJoints \"shoulderL\"  rotations 0 0 1 -1.5707963") +
                               "MannequinSkin { mannequin USE Model }\n");
  // The skin is a sibling of the mannequin; read the scene and find it.
  SceneRoot root = readFile(path);
  ASSERT_TRUE(root);
  auto* model = find<Mannequin>(root.get(), "Model");
  auto* skin = find<MannequinSkin>(root.get());
  ASSERT_TRUE(skin);
  SoGetBoundingBoxAction bbox(SbViewportRegion(100, 100));
  bbox.apply(skin);
  EXPECT_EQ(skin->lastError(), "");
  const SbBox3f box = bbox.getBoundingBox();
  // Rotated about the shoulder: x 0.55..0.6 -> y 1.42 - (0.35..0.4); z unchanged.
  EXPECT_NEAR(box.getMin()[1], 1.42 - 0.40, 1e-4);
  EXPECT_NEAR(box.getMax()[1], 1.42 - 0.35, 1e-4);
  EXPECT_NEAR(box.getMin()[0], 0.2 - 0.02, 1e-4);
  // Each skin vertex keeps its place relative to the forearm's volume: as deep inside
  // it posed as at rest.
  std::vector<double> posed;
  for (const figment::Vec3& v : model->posedBody().vertices) {
    figment::Contact c;
    ASSERT_TRUE(model->collider()->contact(v, 0.0, 0.05, c));
    posed.push_back(c.distance);
  }
  model->rotatedJoints.setNum(0);
  model->rotations.setNum(0);
  ASSERT_EQ(model->posedBody().vertices.size(), posed.size());
  for (size_t i = 0; i < posed.size(); ++i) {
    figment::Contact c;
    ASSERT_TRUE(model->collider()->contact(model->posedBody().vertices[i], 0.0, 0.05, c));
    EXPECT_NEAR(c.distance, posed[i], 1e-6);
    EXPECT_LT(c.distance, -0.01);
  }
  // Only the parts asked for.
  skin->parts.setValue("handL");
  bbox.apply(skin);
  EXPECT_TRUE(bbox.getBoundingBox().isEmpty());
}

TEST_F(MannequinTest, AnExactPartCollidesWithItsOwnTrianglesAndFollowsThePose) {
  // The forearm as its own triangles (a closed 4 cm box around it, x 0.5-0.65) instead
  // of a capsule; the torso keeps its radial volume: a method per part.
  TempDir dir;
  dir.file("arm.obj",
           "v 0.5 1.40 -0.02\nv 0.65 1.40 -0.02\nv 0.5 1.44 -0.02\nv 0.65 1.44 -0.02\n"
           "v 0.5 1.40 0.02\nv 0.65 1.40 0.02\nv 0.5 1.44 0.02\nv 0.65 1.44 0.02\n"
           "f 1 5 7 3\nf 2 4 8 6\nf 1 2 6 5\nf 3 7 8 4\nf 1 3 4 2\nf 5 6 8 7\n");
  const std::string path =
      dir.file("scene.iv", mannequinScene("body DEF Arm MeshFile { fileName \"arm.obj\" }",
                                          std::string(kJoints) + "ExactVolume { part \"forearmL\" }\n" + kTorso));
  SceneRoot root = readFile(path);
  ASSERT_TRUE(root);
  auto* model = find<Mannequin>(root.get(), "Model");
  figment::Contact c;
  ASSERT_TRUE(inContact(*model->collider(), {0.575, 1.42, 0.0}, c));
  EXPECT_NEAR(c.distance, -0.02, 1e-9) << "the box's faces are 2 cm from its axis";
  EXPECT_FALSE(inContact(*model->collider(), {0.575, 1.42, 0.03}, c));
  EXPECT_TRUE(inContact(*model->collider(), {0.0, 1.3, 0.0}, c)) << "the torso's radial volume";
  model->rotatedJoints.setValue("shoulderL");
  model->rotations.setValue(SbRotation(SbVec3f(0, 0, 1), -1.5707963f));
  ASSERT_TRUE(inContact(*model->collider(), {0.2, 1.42 - 0.375, 0.0}, c));
  EXPECT_NEAR(c.distance, -0.02, 1e-6);
}

TEST_F(MannequinTest, ExactPartsCollideWithTheirTrianglesInsteadOfTheirVolumes) {
  // The forearm capsule stays in the scene; exactParts puts the forearm's triangles (the
  // 4 cm box) in its place, in the field or for one collider (a tolerance's mix).
  TempDir dir;
  dir.file("arm.obj",
           "v 0.5 1.40 -0.02\nv 0.65 1.40 -0.02\nv 0.5 1.44 -0.02\nv 0.65 1.44 -0.02\n"
           "v 0.5 1.40 0.02\nv 0.65 1.40 0.02\nv 0.5 1.44 0.02\nv 0.65 1.44 0.02\n"
           "f 1 5 7 3\nf 2 4 8 6\nf 1 2 6 5\nf 3 7 8 4\nf 1 3 4 2\nf 5 6 8 7\n");
  const std::string path = dir.file("scene.iv", mannequinScene("body DEF Arm MeshFile { fileName \"arm.obj\" }"));
  SceneRoot root = readFile(path);
  ASSERT_TRUE(root);
  auto* model = find<Mannequin>(root.get(), "Model");
  const figment::Vec3 onAxis(0.575, 1.42, 0.0);
  figment::Contact c;
  ASSERT_TRUE(inContact(*model->collider(), onAxis, c));
  EXPECT_LT(c.distance, -0.03) << "the capsule is 4 cm round its axis";
  int forearm = 0;
  while (model->skeleton().parts.at(forearm).name != "forearmL") ++forearm;
  ASSERT_TRUE(inContact(*model->colliderWithExactParts({forearm}), onAxis, c));
  EXPECT_NEAR(c.distance, -0.02, 1e-9) << "the box's faces are 2 cm from its axis";
  EXPECT_TRUE(inContact(*model->colliderWithExactParts({forearm}), {0.0, 1.3, 0.0}, c)) << "the torso's volume";

  model->exactParts.setValue("forearmL");
  ASSERT_TRUE(inContact(*model->collider(), onAxis, c));
  EXPECT_NEAR(c.distance, -0.02, 1e-9);
  const figment::CollisionBody::Description d = model->describeBody();
  EXPECT_EQ(d.counts, (std::vector<std::pair<std::string, int>>{
                          {"capsule_volumes", 0}, {"radial_volumes", 1}, {"exact_parts", 1}}));
  model->body.setValue(nullptr);
  EXPECT_THROW(model->collider(), std::invalid_argument) << "its triangles need the body";
}

TEST_F(MannequinTest, AnExactPartNeedsABody) {
  CapturedErrors errors;
  SceneRoot root = readString(mannequinScene("", std::string(kJoints) + "ExactVolume { part \"forearmL\" }\n"));
  ASSERT_TRUE(root) << errors.all();
  EXPECT_THROW(find<Mannequin>(root.get(), "Model")->collider(), std::invalid_argument);
}

TEST_F(MannequinTest, ClothDropsOntoTheForearmAndStaysOutside) {
  // A 16 cm square of cloth 5 cm above the forearm capsule (top at y = 1.46).
  const Grid g = grid(9, 0.16, 1.51, 0.575, 0.0);
  SceneRoot root = readString(mannequinScene("") +
                              "Separator { DEF Cloth Coordinate3 { point = DEF Drape ClothEngine {\n"
                              "  restPoints [ " +
                              g.points + " ] coordIndex [ " + g.coordIndex +
                              " ]\n"
                              "  body USE Model  maxTime 0.25  clearance 0.002 } . positions } }\n");
  ASSERT_TRUE(root);
  auto* cloth = find<SoCoordinate3>(root.get(), "Cloth");
  auto* engine = static_cast<ClothEngine*>(SoBase::getNamedBase("Drape", ClothEngine::getClassTypeId()));
  ASSERT_GT(cloth->point.getNum(), 0);
  EXPECT_EQ(engine->lastError(), "");
  figment::Capsule forearm(find<CapsuleVolume>(root.get(), "Forearm")->parameters());
  float lowestOverArm = 10.0f;
  for (int i = 0; i < cloth->point.getNum(); ++i) {
    const SbVec3f& p = cloth->point[i];
    EXPECT_FALSE(forearm.contains({p[0], p[1], p[2]})) << "node " << i;
    if (std::abs(p[2]) < 0.01f && std::abs(p[0] - 0.575f) < 0.05f) lowestOverArm = std::min(lowestOverArm, p[1]);
  }
  EXPECT_LT(lowestOverArm, 1.47f) << "it came down onto the arm";
}

struct BadMannequin {
  std::string fields, children, expected;
};
class MannequinBadInput : public ::testing::TestWithParam<BadMannequin> {
 protected:
  void SetUp() override { initCoin(); }
};

TEST_P(MannequinBadInput, IsAReadErrorNamingTheFieldAndValue) {
  const BadMannequin& bad = GetParam();
  CapturedErrors errors;
  SceneRoot root =
      readString(bad.children.empty() ? mannequinScene(bad.fields) : mannequinScene(bad.fields, bad.children));
  EXPECT_FALSE(root);
  EXPECT_NE(errors.all().find(bad.expected), std::string::npos) << errors.all();
}

INSTANTIATE_TEST_SUITE_P(
    Fields, MannequinBadInput,
    ::testing::Values(
        BadMannequin{"rotatedJoints \"elbow\"  rotations 0 0 1 1", "", "rotatedJoints[0] = \"elbow\" is not a joint"},
        BadMannequin{"rotatedJoints [ \"elbowL\", \"kneeL\" ]  rotations 0 0 1 1", "",
                     "rotatedJoints has 2 names but rotations has 1 values"},
        BadMannequin{"height 3", "", "height"}, BadMannequin{"blendRadius 0", "", "blendRadius = 0"},
        BadMannequin{"exactParts [ \"forearmL\", \"elbow\" ]", "", "exactParts[1] = \"elbow\" is not a part"},
        BadMannequin{"", std::string(kJoints) + "CapsuleVolume { part \"elbow\" }\n",
                     "CapsuleVolume: part = \"elbow\" is not a part"},
        BadMannequin{"", std::string(kJoints) + "DEF C CapsuleVolume { part \"handL\"  x -1 }\n",
                     "CapsuleVolume 'C': x = -1"},
        BadMannequin{
            "", std::string(kJoints) + "RadialDepthVolume { part \"head\"  harmonics 2  coefficients [ 1 2 3 ] }\n",
            "coefficients has 3 values"},
        BadMannequin{"", kForearm, "has 0 SkeletonJoints below it"},
        BadMannequin{"", "SkeletonJoints { names \"pelvis\"  positions 0 0 0 }\n" + std::string(kForearm),
                     "names has no \"waist\""}));
