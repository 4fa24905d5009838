// Mannequin.showVolumes in pictures: the posed volumes drawn as wireframes in their
// colour, over the body, only when shown (what figment-view --show-volumes switches on).
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include <string>

#include "guard/SceneFile.h"
#include "headless/InitHeadless.h"
#include "nodes/body/Mannequin.h"
#include "session/SceneRenderer.h"
#include "session/SceneStaging.h"
#include "support/Pixels.h"
#include "support/RenderedImage.h"
#include "support/TPoseSkeleton.h"
#include "support/TempDir.h"

using namespace figment::session;
using figment::test::Image;

namespace {

constexpr ImageSize kSize{200, 200};

// A T-posed skeleton, a forearm capsule along +x and a red box (the "body") inside it;
// lines in pure green, flat colours.
const std::string kScene = std::string(
                               "#Inventor V2.1 ascii\n"
                               "Separator {\n"
                               "  LightModel { model BASE_COLOR }\n"
                               "  DEF Model Mannequin {\n"
                               "    volumeColor 0 1 0\n") +
                           figment::test::kTPoseJoints + figment::test::kForearmCapsule +
                           "  }\n"
                           "  BaseColor { rgb 1 0 0 }\n"
                           "  Separator { Translation { translation 0.575 1.42 0 }\n"
                           "              Cube { width 0.3 height 0.05 depth 0.05 } }\n"
                           "}\n";

class VolumeDrawing : public ::testing::Test {
 protected:
  void SetUp() override {
    figment::initHeadless();
    std::string error;
    scene_ = figment::guard::readScene(dir_.file("volumes.iv", kScene), error);
    ASSERT_NE(scene_, nullptr) << error;
    scene_->ref();
    SoSearchAction search;
    search.setName("Model");
    search.apply(scene_);
    model_ = static_cast<Mannequin*>(search.getPath()->getTail());
  }
  void TearDown() override {
    if (scene_) scene_->unref();
  }
  // Front view of the arm's rest place, the same camera for every picture.
  Image render() const {
    SoSeparator* root = stageScene(scene_, kSize, ViewDirection{0.0, 0.0});
    root->ref();
    Image image = figment::test::renderedImage(root, kSize);
    root->unref();
    return image;
  }
  static double meanRow(const Image& image, figment::test::Rgb colour) {
    double sum = 0.0;
    int n = 0;
    for (int i = 0; i < image.width * image.height; ++i)
      if (image.is(i, colour)) sum += i / image.width, ++n;
    return n ? sum / n : -1.0;
  }

  figment::test::TempDir dir_;
  SoSeparator* scene_ = nullptr;
  Mannequin* model_ = nullptr;
};

}  // namespace

TEST_F(VolumeDrawing, NothingIsDrawnUnlessShown) {
  const Image hidden = render();
  EXPECT_EQ(hidden.count(figment::test::kGreen), 0);
  EXPECT_GT(hidden.count(figment::test::kRed), 500) << "the body";
}

TEST_F(VolumeDrawing, ShownVolumesAreWireframesOverTheBody) {
  model_->showVolumes = TRUE;
  const Image shown = render();
  const int green = shown.count(figment::test::kGreen);
  EXPECT_GT(green, 300);
  // Lines, not a filled shape: the body shows between them.
  EXPECT_GT(shown.count(figment::test::kRed), 200);
  // The capsule encloses the body: its front lines cover some body pixels.
  const Image hidden = (model_->showVolumes = FALSE, render());
  const std::vector<bool> body = hidden.where(figment::test::kRed);
  EXPECT_GT(shown.countWithin(figment::test::kGreen, body), 50);
}

TEST_F(VolumeDrawing, ShownVolumesFollowThePose) {
  // The camera frames what is drawn, so rows are compared with the body's (the red box
  // at the arm's rest place, which does not move).
  model_->showVolumes = TRUE;
  const Image rest = render();
  EXPECT_NEAR(meanRow(rest, figment::test::kGreen), meanRow(rest, figment::test::kRed), 3.0);
  // The arm turned down at the shoulder: its wireframe goes below the box (rows count
  // from the bottom: glReadPixels order).
  model_->rotatedJoints.setValue("shoulderL");
  model_->rotations.setValue(SbRotation(SbVec3f(0, 0, 1), -1.5707963f));
  const Image posed = render();
  EXPECT_LT(meanRow(posed, figment::test::kGreen), meanRow(posed, figment::test::kRed) - 20);
}
