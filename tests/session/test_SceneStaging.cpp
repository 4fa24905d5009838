// The framing camera sees the whole scene from the asked direction, and staging adds
// a light only where the scene has none.

#include <Inventor/SbViewVolume.h>
#include <Inventor/nodes/SoCube.h>
#include <Inventor/nodes/SoDirectionalLight.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "headless/InitHeadless.h"
#include "session/SceneStaging.h"

using namespace figment::session;

namespace {

// The box's corners in normalised screen coordinates ([0,1] x [0,1] is the image); when
// `tight`, one of them on the margin.
void expectInView(SoPerspectiveCamera* camera, const SbBox3f& box, float aspect, bool tight = true) {
  const SbViewVolume volume = camera->getViewVolume(aspect);
  float minX = 1, maxX = 0, minY = 1, maxY = 0, farthest = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const SbVec3f p((corner & 1) ? box.getMax()[0] : box.getMin()[0], (corner & 2) ? box.getMax()[1] : box.getMin()[1],
                    (corner & 4) ? box.getMax()[2] : box.getMin()[2]);
    SbVec3f screen;
    volume.projectToScreen(p, screen);
    minX = std::min(minX, screen[0]), maxX = std::max(maxX, screen[0]);
    minY = std::min(minY, screen[1]), maxY = std::max(maxY, screen[1]);
    farthest = std::max({farthest, std::abs(screen[0] - 0.5f), std::abs(screen[1] - 0.5f)});
  }
  EXPECT_GE(minX, 0.0f);
  EXPECT_LE(maxX, 1.0f);
  EXPECT_GE(minY, 0.0f);
  EXPECT_LE(maxY, 1.0f);
  // ...and one corner reaches the 5% margin: the camera is no farther than needed.
  if (tight) {
    EXPECT_NEAR(farthest, 0.5f / 1.05f, 1e-3f);
  }
}

}  // namespace

TEST(SceneStaging, FramingCameraSeesTheWholeBoxFromEveryDirection) {
  figment::initHeadless();
  const SbBox3f box(SbVec3f(-0.5f, 0.0f, -0.2f), SbVec3f(0.5f, 1.7f, 0.3f));  // a body-like box
  for (float aspect : {4.0f / 3.0f, 0.75f, 1.0f})
    for (const ViewDirection view :
         {ViewDirection{0, 0}, ViewDirection{90, 0}, ViewDirection{215, 30}, ViewDirection{-20, -60}}) {
      SCOPED_TRACE(testing::Message() << "aspect " << aspect << " view " << view.azimuth << "," << view.elevation);
      SoPerspectiveCamera* camera = framingCamera(box, view, aspect);
      camera->ref();
      expectInView(camera, box, aspect);
      camera->unref();
    }
}

TEST(SceneStaging, AFramingCameraKeepsADistanceItIsGiven) {
  // The views of a turntable share the largest of their framing distances: the camera
  // then sits that far from the box's centre, and the box still fits every view.
  figment::initHeadless();
  const SbBox3f box(SbVec3f(-0.8f, 0.0f, -0.1f), SbVec3f(0.8f, 1.7f, 0.1f));  // arms out
  const float front = framingDistance(box, {0, 0}, 0.75f), side = framingDistance(box, {90, 0}, 0.75f);
  // In a portrait picture the arms pointing at the camera need it farther away.
  EXPECT_GT(side, 1.03f * front);
  for (const ViewDirection view : {ViewDirection{0, 0}, ViewDirection{90, 0}}) {
    SoPerspectiveCamera* camera = framingCamera(box, view, 0.75f, side);
    camera->ref();
    EXPECT_NEAR((camera->position.getValue() - box.getCenter()).length(), side, 1e-4f * side) << view.azimuth;
    EXPECT_FLOAT_EQ(camera->focalDistance.getValue(), side);
    expectInView(camera, box, 0.75f, view.azimuth == 90.0);
    camera->unref();
  }
  SoPerspectiveCamera* own = framingCamera(box, {0, 0}, 0.75f);
  own->ref();
  EXPECT_NEAR(own->focalDistance.getValue(), front, 1e-5f) << "no distance given: the view's own";
  own->unref();
}

TEST(SceneStaging, CameraSitsInTheAskedDirection) {
  figment::initHeadless();
  const SbBox3f box(SbVec3f(-1, -1, -1), SbVec3f(1, 1, 1));
  const struct {
    ViewDirection view;
    SbVec3f direction;
  } cases[] = {{{0, 0}, {0, 0, 1}},
               {{90, 0}, {1, 0, 0}},
               {{180, 0}, {0, 0, -1}},
               {{270, 0}, {-1, 0, 0}},
               {{0, 45}, {0, float(M_SQRT1_2), float(M_SQRT1_2)}}};
  for (const auto& c : cases) {
    SoPerspectiveCamera* camera = framingCamera(box, c.view, 1.0f);
    camera->ref();
    SbVec3f position = camera->position.getValue();
    position.normalize();
    EXPECT_NEAR((position - c.direction).length(), 0.0f, 1e-5f) << c.view.azimuth << "," << c.view.elevation;
    SbVec3f up;
    camera->orientation.getValue().multVec(SbVec3f(0, 1, 0), up);
    EXPECT_GT(up[1], 0.0f) << "y is up";
    camera->unref();
  }
}

TEST(SceneStaging, AddsALightOnlyWhenTheSceneHasNone) {
  figment::initHeadless();
  const auto countLights = [](SoSeparator* root) {
    int lights = 0;
    for (int i = 0; i < root->getNumChildren(); ++i)
      lights += root->getChild(i)->isOfType(SoDirectionalLight::getClassTypeId());
    return lights;
  };
  auto* dark = new SoSeparator;
  dark->ref();
  dark->addChild(new SoCube);
  SoSeparator* staged = stageScene(dark, {64, 48}, std::nullopt);
  staged->ref();
  EXPECT_EQ(countLights(staged), 1);
  EXPECT_TRUE(staged->getChild(0)->isOfType(SoPerspectiveCamera::getClassTypeId()));
  staged->unref();

  auto* lit = new SoSeparator;
  lit->ref();
  lit->addChild(new SoDirectionalLight);
  lit->addChild(new SoCube);
  staged = stageScene(lit, {64, 48}, std::nullopt);
  staged->ref();
  EXPECT_EQ(countLights(staged), 0);
  staged->unref();
  lit->unref();
  dark->unref();
}

TEST(SceneStaging, KeepsTheScenesCameraUnlessAViewIsAsked) {
  figment::initHeadless();
  auto* scene = new SoSeparator;
  scene->ref();
  auto* own = new SoPerspectiveCamera;
  scene->addChild(own);
  scene->addChild(new SoCube);
  SoSeparator* staged = stageScene(scene, {64, 48}, std::nullopt);
  staged->ref();
  EXPECT_EQ(scene->getChild(0), own);
  EXPECT_FALSE(staged->getChild(0)->isOfType(SoPerspectiveCamera::getClassTypeId()));
  staged->unref();

  staged = stageScene(scene, {64, 48}, ViewDirection{90, 0});
  staged->ref();
  EXPECT_TRUE(staged->getChild(0)->isOfType(SoPerspectiveCamera::getClassTypeId()));
  EXPECT_EQ(scene->findChild(own), -1) << "the scene's camera no longer overrides the asked view";
  staged->unref();
  scene->unref();
}
