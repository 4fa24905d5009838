// A Mannequin request's scene, built in code: the lights of its preset, the mannequin at the
// request's size factors and pose, one engine per garment innermost first, an outer one
// colliding with the garments beneath; a pattern follows the stature and keeps its girth
// (the paper's patterns come in one size);
// a fit map colours each garment point by its stretch, and without one each garment shows the
// colour asked (in its picture's pixels); each garment is drawn through one level of display
// mesh, as the shipped scenes draw theirs.

#include <Inventor/SbBox3f.h>
#include <Inventor/SoDB.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoDirectionalLight.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoMaterialBinding.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "headless/OsmesaForCoin.h"
#include "nodes/Init.h"
#include "nodes/SceneSearch.h"
#include "nodes/body/CollisionGroup.h"
#include "nodes/body/Mannequin.h"
#include "nodes/body/MeshFile.h"
#include "nodes/cloth/ClothEngine.h"
#include "nodes/render/ClothingLayer.h"
#include "serve/scene/OutfitScene.h"
#include "serve/scene/Wardrobe.h"
#include "session/SceneRenderer.h"
#include "session/SceneSession.h"
#include "sim/fit/FitMap.h"
#include "support/PngPixels.h"
#include "support/TempDir.h"

using namespace figment::serve;

namespace {

using figment::test::Image;
using figment::test::readPng;
using figment::test::Rgb;

constexpr figment::session::ImageSize kSize{120, 150};
// A pixel shows a colour when its RGB lies within kHueAngle of the colour's direction: lit
// cloth scales its colour and adds a little grey (the ambient floor of 10, a highlight),
// which turns it by less (97 % of a red shirt's pixels here), while the default skin lies
// 38 degrees from red, the grey background 55 and another primary 90.
constexpr double kHueAngle = 20.0;  // degrees
constexpr Rgb kRedShirt{255, 0, 0}, kGreenShirt{0, 255, 0}, kMagenta{255, 0, 255}, kBlueBand{0, 0, 255};

// `parameters` with body=mannequin: these scenes are the Mannequin's (a made body's are
// tested through the service, tests/serve/scenarios/).
QueryParameters onTheMannequin(QueryParameters parameters) {
  parameters.emplace_back("body", "mannequin");
  return parameters;
}

class OutfitSceneTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    figment::useOsmesaForCoin();  // pictures, off-screen: before Coin starts
    SoDB::init();
    figment::init();
    wardrobe_ = new Wardrobe;
    ASSERT_EQ(wardrobe_->read(FIGMENT_SOURCE_DIR "/scenes"), "");
  }
  static void TearDownTestSuite() { delete wardrobe_; }

  // The scene for `parameters`, referenced; its engines in scene order.
  static SoSeparator* scene(const QueryParameters& parameters, std::vector<ClothEngine*>& engines) {
    auto parsed = RenderRequest::parse(onTheMannequin(parameters));
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

  // The request's scene drawn at kSize from the front, decoded from its PNG file as the
  // service's answer would be. The colour is under test, not the drape: each engine takes
  // one step (the garment stays about where it was cut, round the mannequin), not the
  // seconds of a full drape.
  Image picture(const QueryParameters& parameters) const {
    auto parsed = RenderRequest::parse(onTheMannequin(parameters));
    EXPECT_TRUE(std::holds_alternative<RenderRequest>(parsed));
    if (!std::holds_alternative<RenderRequest>(parsed)) return {};
    std::vector<OutfitScene::FitMapGarment> fitMaps;
    figment::session::SceneSession session;
    session.adopt(OutfitScene::build(std::get<RenderRequest>(parsed), *wardrobe_, {}, &fitMaps));
    for (ClothEngine* engine : session.engines()) engine->maxTime = engine->timeStep.getValue();
    session.drape();
    EXPECT_EQ(session.firstError(), "");
    OutfitScene::paintFitMaps(fitMaps);
    SoSeparator* staged = session.stage(kSize, figment::session::ViewDirection{0.0, 10.0});
    EXPECT_NE(staged, nullptr);
    if (!staged) return {};
    figment::session::SceneRenderer renderer(kSize);
    EXPECT_EQ(renderer.render(staged), "");
    const std::string path = (dir_.path() / "outfit.png").string();
    EXPECT_EQ(renderer.writePng(path), "");
    return readPng(path);
  }

  static Wardrobe* wardrobe_;
  figment::test::TempDir dir_;
};

Wardrobe* OutfitSceneTest::wardrobe_ = nullptr;

// Pixels whose colour differs between two pictures of one size by more than 8 levels in a
// channel.
std::vector<bool> changed(const Image& a, const Image& b) {
  std::vector<bool> mask(size_t(a.width) * a.height, false);
  if (a.width != b.width || a.height != b.height) return mask;
  for (size_t i = 0; i < mask.size(); ++i)
    mask[i] = !a.is(int(i), Rgb{b.rgb[3 * i], b.rgb[3 * i + 1], b.rgb[3 * i + 2]});
  return mask;
}

// Pixels of `colour` (kHueAngle) where `mask` is set.
int countColour(const Image& image, Rgb colour, const std::vector<bool>& mask) {
  const double cosine = std::cos(kHueAngle * M_PI / 180.0);
  const double c = std::sqrt(double(colour.r * colour.r + colour.g * colour.g + colour.b * colour.b));
  int n = 0;
  for (int i = 0; i < image.width * image.height; ++i) {
    const unsigned char* p = &image.rgb[3 * size_t(i)];
    const double length = std::sqrt(double(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
    n += mask[i] && length > 0 && (p[0] * colour.r + p[1] * colour.g + p[2] * colour.b) > cosine * length * c;
  }
  return n;
}

}  // namespace

TEST_F(OutfitSceneTest, LayersDrapeInsideOutOnTheMannequinAndTheGarmentsBeneath) {
  std::vector<ClothEngine*> engines;
  SoSeparator* root = scene({{"outfit", "tshirt,skirt,dress"}, {"light", "soft"}, {"pose", "relaxed"}}, engines);
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
  EXPECT_EQ(lights, int(ShopperChoices::light("soft")->lights.size()));
  root->unref();
}

// Drawn smooth as scenes/dress.iv is (issue 29): every garment's ClothingLayer one level.
TEST_F(OutfitSceneTest, EachGarmentDrawsADisplayMesh) {
  std::vector<ClothEngine*> engines;
  SoSeparator* root = scene({{"outfit", "tshirt,dress"}}, engines);
  SoSearchAction search;
  search.setType(ClothingLayer::getClassTypeId());
  search.setInterest(SoSearchAction::ALL);
  search.apply(root);
  ASSERT_EQ(search.getPaths().getLength(), 2);
  for (int i = 0; i < 2; ++i) {
    const auto* layer = static_cast<const ClothingLayer*>(search.getPaths()[i]->getTail());
    EXPECT_EQ(layer->displaySubdivision.getValue(), 1) << i;
    EXPECT_EQ(layer->fieldProblem(), "") << i;
  }
  root->unref();
}

TEST_F(OutfitSceneTest, APatternFollowsTheStatureAndKeepsItsGirth) {
  std::vector<ClothEngine*> m, tall;
  SoSeparator* a = scene({{"outfit", "dress"}}, m);
  SoSeparator* b = scene({{"outfit", "dress"}, {"stature", "1.820"}}, tall);
  const float floor = wardrobe_->heightOrigin()[1];
  const double height = 1.820 / ShopperChoices::measure("stature").reference;
  const double defaultHeight = 1.659 / ShopperChoices::measure("stature").reference;  // the default, rounded to mm
  const SbBox3f boxM = restBox(m[0]), boxTall = restBox(tall[0]);
  // Heights above the floor scale with the stature (float rounding: 1e-4 of a metre).
  EXPECT_NEAR((boxTall.getMax()[1] - floor) / (boxM.getMax()[1] - floor), height / defaultHeight, 1e-4);
  // The pattern as cut otherwise: its rest points are the file's, scaled about the origin.
  const MeshFile* pattern = wardrobe_->pattern("dress");
  ASSERT_EQ(m[0]->restPoints.getNum(), pattern->point.getNum());
  const SbVec3f origin = wardrobe_->heightOrigin();
  const float scale = float(defaultHeight);
  for (int i = 0; i < pattern->point.getNum(); i += 97)
    EXPECT_LT((m[0]->restPoints[i] - (origin + scale * (pattern->point[i] - origin))).length(), 1e-5f) << i;
  a->unref();
  b->unref();
}

TEST_F(OutfitSceneTest, AFitMapColoursEachPointByItsStretchBand) {
  auto parsed = RenderRequest::parse(onTheMannequin({{"outfit", "tshirt,skirt"}, {"fitmap", "stretch"}}));
  ASSERT_TRUE(std::holds_alternative<RenderRequest>(parsed));
  std::vector<OutfitScene::FitMapGarment> fitMaps;
  SoSeparator* root = OutfitScene::build(std::get<RenderRequest>(parsed), *wardrobe_, {}, &fitMaps);
  root->ref();
  ASSERT_EQ(fitMaps.size(), 2u);  // each garment, innermost first
  EXPECT_EQ(fitMaps[0].fabric, "jersey");
  // Drawn per vertex (a ClothingLayer draws one material): a binding per garment.
  SoSearchAction search;
  search.setType(SoMaterialBinding::getClassTypeId());
  search.setInterest(SoSearchAction::ALL);
  search.apply(root);
  EXPECT_EQ(search.getPaths().getLength(), 2);
  // The drape's positions given by hand: the T-shirt as cut is at rest (blue), 20 % larger
  // every way it is past jersey's 10 % limit (red).
  // (Coordinates of the test's own: the scene's would drape when read.)
  const OutfitScene::FitMapGarment& shirt = fitMaps[0];
  const int n = int(shirt.rest.vertices.size());
  ASSERT_GT(n, 100);
  auto* drape = new SoCoordinate3;
  drape->ref();
  const auto paintedAt = [&](float scale) {
    std::vector<SbVec3f> points;
    for (const figment::Vec3& p : shirt.rest.vertices)
      points.push_back(SbVec3f(float(p.x()), float(p.y()), float(p.z())) * scale);
    drape->point.setValues(0, n, points.data());
    OutfitScene::FitMapGarment byHand = shirt;
    byHand.coordinates = drape;
    OutfitScene::paintFitMaps({byHand});
    const SoMFColor& colours = shirt.material->diffuseColor;
    return std::vector<SbColor>(colours.getValues(0), colours.getValues(0) + colours.getNum());
  };
  const auto share = [n](const std::vector<SbColor>& colours, int band) {
    const figment::Vec3 c = figment::fitMapColour(band);
    return double(std::count(colours.begin(), colours.end(), SbColor(float(c.x()), float(c.y()), float(c.z())))) / n;
  };
  EXPECT_EQ(paintedAt(1.0f).size(), size_t(n));
  EXPECT_GT(share(paintedAt(1.0f), 0), 0.99);
  EXPECT_GT(share(paintedAt(1.2f), figment::kFitMapBands - 1), 0.99);
  drape->unref();
  root->unref();
}

// The garment in the colour the request asks, decoded from the picture's pixels: a red
// T-shirt shows red and no green, a green one green and no red, over the same pixels (the
// shirt's: where the two pictures differ). The control: a shirt asked in magenta (a colour
// the fit map's blue-to-red bands never draw) with a fit map is painted by its bands (blue,
// about at rest) and shows no magenta, as a garment that lost its colour would.
TEST_F(OutfitSceneTest, WithoutAFitMapTheGarmentsKeepTheirColours) {
  std::vector<OutfitScene::FitMapGarment> fitMaps;
  SoSeparator* root =
      OutfitScene::build(std::get<RenderRequest>(RenderRequest::parse(onTheMannequin({}))), *wardrobe_, {}, &fitMaps);
  root->ref();
  EXPECT_TRUE(fitMaps.empty());
  root->unref();
  const Image red = picture({{"outfit", "tshirt:ff0000"}});
  const Image green = picture({{"outfit", "tshirt:00ff00"}});
  const Image fitMap = picture({{"outfit", "tshirt:ff00ff"}, {"fitmap", "stretch"}});
  ASSERT_GT(red.width, 0);
  // The shirt: the pixels the colour changes (the rest of the two pictures is the same
  // scene, drawn the same). It covers about 7 % of the picture: the mask is not empty.
  const std::vector<bool> shirt = changed(red, green), everywhere(shirt.size(), true);
  const int shirtPixels = int(std::count(shirt.begin(), shirt.end(), true));
  ASSERT_GT(shirtPixels, kSize.width * kSize.height / 50);
  // In the colour asked: all but the highlights (a tenth to spare), and that colour nowhere
  // else; the other's nowhere.
  EXPECT_GT(countColour(red, kRedShirt, shirt), 0.9 * shirtPixels);
  EXPECT_GT(countColour(green, kGreenShirt, shirt), 0.9 * shirtPixels);
  EXPECT_EQ(countColour(red, kRedShirt, everywhere), countColour(red, kRedShirt, shirt));
  EXPECT_EQ(countColour(green, kGreenShirt, everywhere), countColour(green, kGreenShirt, shirt));
  EXPECT_EQ(countColour(red, kGreenShirt, everywhere), 0);
  EXPECT_EQ(countColour(green, kRedShirt, everywhere), 0);
  // The control: under its fit map the shirt has lost the colour asked, and the count says so.
  EXPECT_EQ(countColour(fitMap, kMagenta, everywhere), 0);
  EXPECT_GT(countColour(fitMap, kBlueBand, shirt), shirtPixels / 2);
}
