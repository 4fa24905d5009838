// HumanBody.baseLayer on MakeHuman's body: the underwear is drawn in its colour over the
// skin it covers and goes with the field; a women's layer reaches over the bust, a men's
// stops under the waist; every point lies just off the skin, standing and sitting. Skipped
// when MakeHuman's data is absent.
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "guard/SceneFile.h"
#include "headless/InitHeadless.h"
#include "io/MakeHumanFiles.h"
#include "nodes/body/HumanBody.h"
#include "session/SceneRenderer.h"
#include "session/SceneStaging.h"
#include "sim/body/BodyMeasurements.h"
#include "sim/collision/MeshCollider.h"
#include "support/Pixels.h"
#include "support/RenderedImage.h"
#include "support/TempDir.h"

using namespace figment::session;
using figment::test::Image;
using figment::test::Rgb;

namespace {

constexpr ImageSize kLayerPicture{200, 300};

class HumanBodyBaseLayer : public ::testing::Test {
 protected:
  void SetUp() override {
    if (figment::findMakeHumanData().empty()) GTEST_SKIP() << "MakeHuman's data not found";
    figment::initHeadless();
  }
  void TearDown() override {
    if (scene_) scene_->unref();
  }
  // A scene of one HumanBody with `fields`, drawn flat (BASE_COLOR: each pixel its colour).
  HumanBody* read(const std::string& fields) {
    std::string error;
    scene_ = figment::guard::readScene(dir_.file("layer.iv",
                                                 "#Inventor V2.1 ascii\n"
                                                 "Separator {\n"
                                                 "  LightModel { model BASE_COLOR }\n"
                                                 "  DEF Made HumanBody { " +
                                                     fields + " }\n}\n"),
                                       error);
    EXPECT_NE(scene_, nullptr) << error;
    if (!scene_) return nullptr;
    scene_->ref();
    SoSearchAction search;
    search.setName("Made");
    search.apply(scene_);
    return static_cast<HumanBody*>(search.getPath()->getTail());
  }
  Image render() const {
    SoSeparator* root = stageScene(scene_, kLayerPicture, ViewDirection{0.0, 0.0});
    root->ref();
    Image image = figment::test::renderedImage(root, kLayerPicture);
    root->unref();
    return image;
  }
  // Each layer point's signed distance to the body's skin, m.
  static std::vector<double> distancesToTheSkin(const HumanBody& body) {
    const figment::MeshCollider skin(body.collisionSurface());
    std::vector<double> out;
    for (const figment::Vec3& p : body.baseLayerSurface().vertices) {
      figment::Contact contact;
      out.push_back(skin.contact(p, 0.01, 0.02, contact) ? contact.distance : 1.0);
    }
    std::sort(out.begin(), out.end());
    return out;
  }

  figment::test::TempDir dir_;
  SoSeparator* scene_ = nullptr;
};

}  // namespace

TEST_F(HumanBodyBaseLayer, IsDrawnInItsColourOverTheSkinAndGoesWithTheField) {
  HumanBody* body = read("skinTone 6 baseLayer UNDERWEAR baseLayerColor 1 0 0");
  ASSERT_NE(body, nullptr);
  const Rgb monk6{0xa0, 0x7e, 0x56}, red{255, 0, 0};
  const Image dressed = render();
  EXPECT_GT(dressed.count(red), 400);
  body->baseLayer = HumanBody::NONE;
  const Image bare = render();
  EXPECT_EQ(bare.count(red), 0);
  // The layer covers skin: what it drew red is skin again without it (its 1.5 mm lift
  // adds a pixel here and there at the outline).
  EXPECT_NEAR(bare.count(monk6), dressed.count(monk6) + dressed.count(red), 0.03 * dressed.count(red));
  body->baseLayer = HumanBody::UNDERWEAR;
  body->baseLayerColor.setValue(0, 0, 1);
  const Image blue = render();
  EXPECT_EQ(blue.count(red), 0);
  EXPECT_EQ(blue.count(Rgb{0, 0, 255}), dressed.count(red));
}

TEST_F(HumanBodyBaseLayer, ACopiedBodyDrawsTheSameLayer) {
  HumanBody* body = read("skinTone 6 baseLayer UNDERWEAR baseLayerColor 1 0 0");
  ASSERT_NE(body, nullptr);
  const Rgb red{255, 0, 0};
  const int drawn = render().count(red);
  ASSERT_GT(drawn, 400);
  SoSeparator* original = scene_;
  scene_ = static_cast<SoSeparator*>(original->copy());  // the body's copy among the scene's
  scene_->ref();
  original->unref();
  EXPECT_EQ(render().count(red), drawn);
}

TEST_F(HumanBodyBaseLayer, AWomansReachesOverTheBustAndAMansStopsUnderTheWaist) {
  for (const char* gender : {"0", "1"}) {
    HumanBody* body = read(std::string("gender ") + gender + " baseLayer UNDERWEAR");
    ASSERT_NE(body, nullptr);
    const figment::BodyLandmarks at = figment::measureBody(body->restSurface()).landmarks;
    const figment::TriangleMesh layer = body->baseLayerSurface();
    ASSERT_FALSE(layer.vertices.empty()) << "gender " << gender;
    double lowest = 1e9, highest = 0;
    for (const figment::Vec3& p : layer.vertices) lowest = std::min(lowest, p.y()), highest = std::max(highest, p.y());
    EXPECT_LT(lowest, at.crotch) << "gender " << gender;  // the gusset goes under the crotch
    if (std::string(gender) == "0")
      EXPECT_GT(highest, at.bust) << "a women's band over the bust";
    else
      EXPECT_LT(highest, at.waist) << "briefs only";
    scene_->unref();
    scene_ = nullptr;
  }
}

TEST_F(HumanBodyBaseLayer, LiesJustOffTheSkinStandingAndSitting) {
  // Sitting, the thigh's skin folds into the groin's (the rig's crease): the few layer
  // points in the fold lie inside the folded skin, hidden by it, within 2 mm.
  struct Case {
    const char* pose;
    int percentOff;  // this share of the points at least 0.5 mm off the skin
  };
  for (const Case c : {Case{"A_POSE", 99}, Case{"SITTING", 95}}) {
    HumanBody* body = read(std::string("stature 1.68 bustGirth 0.88 waistGirth 0.72 hipGirth 0.96 pose ") + c.pose +
                           " baseLayer UNDERWEAR");
    ASSERT_NE(body, nullptr);
    const std::vector<double> d = distancesToTheSkin(*body);
    ASSERT_GT(d.size(), 500u);
    EXPECT_NEAR(d[d.size() / 2], 0.0015, 0.0002) << c.pose << ": the median point 1.5 mm off";
    EXPECT_GT(d[d.size() * size_t(100 - c.percentOff) / 100], 0.0005) << c.pose;
    EXPECT_GT(d.front(), -0.002) << c.pose;
    EXPECT_LT(d.back(), 0.003) << c.pose << ": none past the cloth's clearance";
    scene_->unref();
    scene_ = nullptr;
  }
}
