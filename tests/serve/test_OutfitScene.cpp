// A request's scene, built in code: the lights of its preset, the mannequin at the
// request's size factors and pose, one engine per garment innermost first, an outer one
// colliding with the garments beneath; a pattern follows the stature and its size widens it.

#include <Inventor/SbBox3f.h>
#include <Inventor/SoDB.h>
#include <Inventor/nodes/SoDirectionalLight.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include "nodes/Init.h"
#include "nodes/SceneSearch.h"
#include "nodes/body/CollisionGroup.h"
#include "nodes/body/Mannequin.h"
#include "nodes/cloth/ClothEngine.h"
#include "serve/OutfitScene.h"
#include "serve/Wardrobe.h"

using namespace figment::serve;

namespace {

class OutfitSceneTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    SoDB::init();
    figment::init();
    wardrobe_ = new Wardrobe;
    ASSERT_EQ(wardrobe_->read(FIGMENT_SOURCE_DIR "/scenes"), "");
  }
  static void TearDownTestSuite() { delete wardrobe_; }

  // The scene for `parameters`, referenced; its engines in scene order.
  static SoSeparator* scene(const RenderRequest::Parameters& parameters, std::vector<ClothEngine*>& engines) {
    auto parsed = RenderRequest::parse(parameters);
    EXPECT_TRUE(std::holds_alternative<RenderRequest>(parsed));
    SoSeparator* root = OutfitScene::build(std::get<RenderRequest>(parsed), *wardrobe_);
    root->ref();
    engines = figment::findClothEngines(root);
    return root;
  }

  static SbBox3f restBox(const ClothEngine* engine) {
    SbBox3f box;
    for (int i = 0; i < engine->restPoints.getNum(); ++i) box.extendBy(engine->restPoints[i]);
    return box;
  }

  static Wardrobe* wardrobe_;
};

Wardrobe* OutfitSceneTest::wardrobe_ = nullptr;

}  // namespace

TEST_F(OutfitSceneTest, LayersDrapeInsideOutOnTheMannequinAndTheGarmentsBeneath) {
  std::vector<ClothEngine*> engines;
  SoSeparator* root = scene({{"outfit", "tshirt:M,skirt:M,dress:L"}, {"light", "soft"}, {"pose", "relaxed"}}, engines);
  ASSERT_EQ(engines.size(), 3u);
  ASSERT_TRUE(engines[0]->body.getValue()->isOfType(Mannequin::getClassTypeId()));
  const auto* model = static_cast<const Mannequin*>(engines[0]->body.getValue());
  EXPECT_EQ(model->rotatedJoints.getNum(), 2);  // relaxed: both elbows
  for (size_t i = 1; i < 3; ++i) {
    ASSERT_TRUE(engines[i]->body.getValue()->isOfType(CollisionGroup::getClassTypeId())) << i;
    const auto* group = static_cast<const CollisionGroup*>(engines[i]->body.getValue());
    EXPECT_EQ(group->body.getValue(), model) << i;
    EXPECT_EQ(group->layers.getNum(), int(i)) << i;  // every garment beneath
  }
  int lights = 0;
  for (int i = 0; i < root->getNumChildren(); ++i)
    lights += root->getChild(i)->isOfType(SoDirectionalLight::getClassTypeId());
  EXPECT_EQ(lights, int(Catalogue::light("soft")->lights.size()));
  root->unref();
}

TEST_F(OutfitSceneTest, APatternFollowsTheStatureAndItsSizeWidensIt) {
  std::vector<ClothEngine*> m, tall, xl;
  SoSeparator* a = scene({{"outfit", "dress:M"}}, m);
  SoSeparator* b = scene({{"outfit", "dress:M"}, {"stature", "1.820"}}, tall);
  SoSeparator* c = scene({{"outfit", "dress:XL"}}, xl);
  const float floor = wardrobe_->heightOrigin()[1];
  const double height = 1.820 / Catalogue::measure("stature").reference;
  const double defaultHeight = 1.659 / Catalogue::measure("stature").reference;  // the default, rounded to mm
  const SbBox3f boxM = restBox(m[0]), boxTall = restBox(tall[0]), boxXl = restBox(xl[0]);
  // Heights above the floor scale with the stature (float rounding: 1e-4 of a metre).
  EXPECT_NEAR((boxTall.getMax()[1] - floor) / (boxM.getMax()[1] - floor), height / defaultHeight, 1e-4);
  // XL is 1.10 the girth of M, at the same heights.
  EXPECT_NEAR((boxXl.getMax()[0] - boxXl.getMin()[0]) / (boxM.getMax()[0] - boxM.getMin()[0]), 1.10, 1e-4);
  EXPECT_NEAR((boxXl.getMax()[2] - boxXl.getMin()[2]) / (boxM.getMax()[2] - boxM.getMin()[2]), 1.10, 1e-4);
  EXPECT_NEAR(boxXl.getMax()[1], boxM.getMax()[1], 1e-5);
  a->unref();
  b->unref();
  c->unref();
}
