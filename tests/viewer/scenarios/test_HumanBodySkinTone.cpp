// HumanBody.skinTone in pictures: the body is drawn in the Monk Skin Tone scale's colour
// of its tone (flat BASE_COLOR lighting, so every body pixel has it exactly), and in the
// scene's own colour with tone 0. Skipped when MakeHuman's data is absent.
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include <string>

#include "guard/SceneFile.h"
#include "headless/InitHeadless.h"
#include "io/MakeHumanFiles.h"
#include "nodes/body/HumanBody.h"
#include "session/SceneRenderer.h"
#include "session/SceneStaging.h"
#include "support/Pixels.h"
#include "support/RenderedImage.h"
#include "support/TempDir.h"

namespace test_HumanBodySkinTone {

using namespace figment::session;
using figment::test::Image;
using figment::test::Rgb;

namespace {

constexpr ImageSize kSize{200, 200};

class HumanBodySkinTone : public ::testing::Test {
 protected:
  void SetUp() override {
    if (figment::findMakeHumanData().empty()) GTEST_SKIP() << "MakeHuman's data not found";
    figment::initHeadless();
    std::string error;
    scene_ = figment::guard::readScene(dir_.file("tone.iv",
                                                 "#Inventor V2.1 ascii\n"
                                                 "Separator {\n"
                                                 "  LightModel { model BASE_COLOR }\n"
                                                 "  BaseColor { rgb 0 1 0 }\n"
                                                 "  DEF Made HumanBody { skinTone 6 }\n"
                                                 "}\n"),
                                       error);
    ASSERT_NE(scene_, nullptr) << error;
    scene_->ref();
    SoSearchAction search;
    search.setName("Made");
    search.apply(scene_);
    body_ = static_cast<HumanBody*>(search.getPath()->getTail());
  }
  void TearDown() override {
    if (scene_) scene_->unref();
  }
  Image render() const {
    SoSeparator* root = stageScene(scene_, kSize, ViewDirection{0.0, 0.0});
    root->ref();
    Image image = figment::test::renderedImage(root, kSize);
    root->unref();
    return image;
  }

  figment::test::TempDir dir_;
  SoSeparator* scene_ = nullptr;
  HumanBody* body_ = nullptr;
};

}  // namespace

TEST_F(HumanBodySkinTone, TheBodyIsDrawnInItsTonesColour) {
  const Rgb monk6{0xa0, 0x7e, 0x56}, green{0, 255, 0};
  const Image toned = render();
  EXPECT_GT(toned.count(monk6), 1000);
  EXPECT_EQ(toned.count(green), 0);
  body_->skinTone = 0;  // the scene's colour
  const Image plain = render();
  EXPECT_EQ(plain.count(monk6), 0);
  EXPECT_NEAR(plain.count(green), toned.count(monk6), 10);  // the same body, the same pixels
}

}  // namespace test_HumanBodySkinTone
