// The paper's layered outfits (§6, Figures 6.2 and 6.3) in pictures that can fail: the
// shipped scenes draped once, recoloured flat (skin red, inner T-shirt green, outer
// garment blue) and rendered from 8 directions around. Inside the outer garment's
// silhouette no T-shirt pixel shows. Under the dress, with the depth buffer alone, some
// do (the layers lie millimetres apart over the chest, so the problem exists); the
// skirt stands centimetres off the T-shirt's hem, and the depth buffer alone gets it
// right too: its control draws the outer garment narrower, into the T-shirt.
//
// The silhouette is where the outer garment, drawn alone with back faces culled, shows
// its outside: through a neckline or over a waistband one sees the garment's inside, and
// the T-shirt rightly covers that.
#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoBaseColor.h>
#include <Inventor/nodes/SoDrawStyle.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoShapeHints.h>
#include <Inventor/nodes/SoTransform.h>
#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <vector>

#include "headless/InitHeadless.h"
#include "nodes/render/ClothingLayer.h"
#include "session/SceneRenderer.h"
#include "session/SceneSession.h"
#include "support/Pixels.h"
#include "support/RenderedImage.h"
#include "viewer/DepthBufferOnly.h"

namespace test_OutfitPixels {

using namespace figment::session;
using namespace figment::viewer;
using figment::test::Image;
using figment::test::Rgb;

namespace {

constexpr ImageSize kSize{240, 280};
const std::vector<double> kEightAzimuths = {0, 45, 90, 135, 180, 225, 270, 315};

// A shipped outfit, draped once, whose parts (the Separators holding the named nodes)
// can be recoloured, hidden and culled.
class Outfit {
 public:
  explicit Outfit(const std::string& file) {
    loaded_ = session_.load(std::string(FIGMENT_SOURCE_DIR) + "/scenes/" + file);
    EXPECT_TRUE(loaded_) << session_.loadError();
    if (!loaded_) return;
    session_.drape();
    EXPECT_EQ(session_.firstError(), "");
  }
  bool ready() const { return loaded_ && session_.firstError().empty(); }

  // The Separator holding the node named `name` (a ClothingLayer or the MannequinSkin).
  SoSeparator* part(const char* name) {
    SoSearchAction search;
    search.setName(name);
    search.apply(session_.scene());
    SoPath* path = search.getPath();
    EXPECT_NE(path, nullptr) << name;
    return path ? dynamic_cast<SoSeparator*>(path->getNodeFromTail(1)) : nullptr;
  }
  // Flat colour: BASE_COLOR lighting and a base colour after the part's own Material.
  void paint(const char* name, Rgb colour) {
    SoSeparator* separator = part(name);
    ASSERT_NE(separator, nullptr);
    int material = 0;
    while (material < separator->getNumChildren() &&
           !separator->getChild(material)->isOfType(SoMaterial::getClassTypeId()))
      ++material;
    ASSERT_LT(material, separator->getNumChildren()) << name << " has no Material";
    auto* base = new SoBaseColor;
    base->rgb.setValue(colour.r / 255.0f, colour.g / 255.0f, colour.b / 255.0f);
    separator->insertChild(base, material + 1);
    auto* flat = new SoLightModel;
    flat->model = SoLightModel::BASE_COLOR;
    separator->insertChild(flat, 0);
  }
  // Renders from `azimuth` with the named parts hidden and, if `culled`, back faces
  // culled in the named part; `narrowed`, if given, drawn `narrowing` narrower about its
  // vertical axis.
  Image render(double azimuth, const std::vector<const char*>& hidden = {}, const char* culled = nullptr,
               const char* narrowed = nullptr, float narrowing = 0.0f) {
    std::vector<std::pair<SoSeparator*, SoNode*>> added;
    if (narrowed) added.emplace_back(part(narrowed), narrower(part(narrowed), narrowing));
    for (const char* name : hidden) {
      auto* invisible = new SoDrawStyle;
      invisible->style = SoDrawStyle::INVISIBLE;
      added.emplace_back(part(name), invisible);
    }
    if (culled) {
      auto* solid = new SoShapeHints;
      solid->vertexOrdering = SoShapeHints::COUNTERCLOCKWISE;
      solid->shapeType = SoShapeHints::SOLID;
      added.emplace_back(part(culled), solid);
    }
    for (auto& [separator, node] : added) {
      // After the part's own ShapeHints, before its shape.
      separator->insertChild(node, separator->getNumChildren() - 1);
    }
    Image image = figment::test::renderedImage(session_.stage(kSize, ViewDirection{azimuth, 10.0}), kSize);
    for (auto& [separator, node] : added) separator->removeChild(node);
    return image;
  }
  // The same view with FIGMENT's hybrid nodes swapped for plain ones.
  Image renderDepthBufferOnly(double azimuth, const char* narrowed = nullptr, float narrowing = 0.0f) {
    // Found before the swap, which replaces the named ClothingLayer.
    SoSeparator* narrowedPart = narrowed ? part(narrowed) : nullptr;
    SoNode* transform = narrowed ? narrower(narrowedPart, narrowing) : nullptr;
    if (transform) narrowedPart->insertChild(transform, narrowedPart->getNumChildren() - 1);
    DepthBufferOnly swap(session_.scene());
    swap.use(true);
    Image image = render(azimuth);
    swap.use(false);
    if (transform) narrowedPart->removeChild(transform);
    return image;
  }
  // A transform that draws `separator`'s shape `narrowing` narrower about its vertical axis.
  static SoNode* narrower(SoSeparator* separator, float narrowing) {
    SoGetBoundingBoxAction bound(SbViewportRegion(kSize.width, kSize.height));
    bound.apply(separator);
    auto* transform = new SoTransform;
    transform->scaleFactor.setValue(1.0f - narrowing, 1.0f, 1.0f - narrowing);
    transform->center = bound.getBoundingBox().getCenter();
    return transform;
  }

 private:
  SceneSession session_;
  bool loaded_ = false;
};

struct OutfitCase {
  const char* file;
  const char* outer;              // the outer garment's ClothingLayer
  bool depthBufferShowsTheShirt;  // the depth buffer alone lets T-shirt pixels through
  friend void PrintTo(const OutfitCase& c, std::ostream* out) { *out << c.file; }
};

class OutfitPixels : public ::testing::TestWithParam<OutfitCase> {
 protected:
  static void SetUpTestSuite() { figment::initHeadless(); }
};

}  // namespace

TEST_P(OutfitPixels, NoTShirtPixelInsideTheOuterGarmentFromEightViews) {
  const auto [file, outer, depthBufferShowsTheShirt] = GetParam();
  Outfit outfit(file);
  ASSERT_TRUE(outfit.ready());
  outfit.paint("Skin", figment::test::kRed);
  outfit.paint("Shirt", figment::test::kGreen);
  outfit.paint(outer, figment::test::kBlue);
  int plainTotal = 0, shirtOutside = 0;
  for (double azimuth : kEightAzimuths) {
    const std::vector<bool> silhouette = outfit.render(azimuth, {"Skin", "Shirt"}, outer).where(figment::test::kBlue);
    int silhouettePixels = 0;
    for (bool inside : silhouette) silhouettePixels += inside;
    EXPECT_GT(silhouettePixels, 2000) << file << ", azimuth " << azimuth;
    const Image picture = outfit.render(azimuth);
    EXPECT_EQ(picture.countWithin(figment::test::kGreen, silhouette), 0) << file << ", azimuth " << azimuth;
    shirtOutside += picture.count(figment::test::kGreen);
    plainTotal += outfit.renderDepthBufferOnly(azimuth).countWithin(figment::test::kGreen, silhouette);
  }
  // The T-shirt is in the pictures (its sleeves and collar), and where the layers lie
  // close the depth buffer alone lets it through: the test has something to catch.
  EXPECT_GT(shirtOutside, 8 * 500) << file;
  RecordProperty("depth_buffer_shirt_pixels", plainTotal);
  if (depthBufferShowsTheShirt)
    EXPECT_GT(plainTotal, 0) << file;
  else
    EXPECT_EQ(plainTotal, 0) << file;
}

TEST_P(OutfitPixels, TheControlAnOuterGarmentDrawnIntoTheShirtStillCoversIt) {
  // The outer garment drawn 6 % narrower about its axis, into the T-shirt: the depth
  // buffer alone then shows the T-shirt through it from every side (the dress: 826 to
  // 1,874 pixels; the skirt: 422 to 763), the hybrid nodes still nowhere. The skirt
  // drapes centimetres off the T-shirt, so without this the test above could not tell
  // hybrid rendering from plain.
  const auto [file, outer, depthBufferShowsTheShirt] = GetParam();
  constexpr float kNarrowing = 0.06f;
  Outfit outfit(file);
  ASSERT_TRUE(outfit.ready());
  outfit.paint("Skin", figment::test::kRed);
  outfit.paint("Shirt", figment::test::kGreen);
  outfit.paint(outer, figment::test::kBlue);
  for (double azimuth : {0.0, 90.0, 180.0, 270.0}) {
    const std::vector<bool> silhouette =
        outfit.render(azimuth, {"Skin", "Shirt"}, outer, outer, kNarrowing).where(figment::test::kBlue);
    const int hybrid =
        outfit.render(azimuth, {}, nullptr, outer, kNarrowing).countWithin(figment::test::kGreen, silhouette);
    const int plain =
        outfit.renderDepthBufferOnly(azimuth, outer, kNarrowing).countWithin(figment::test::kGreen, silhouette);
    EXPECT_EQ(hybrid, 0) << file << ", azimuth " << azimuth;
    EXPECT_GT(plain, 100) << file << ", azimuth " << azimuth;
  }
}

INSTANTIATE_TEST_SUITE_P(Outfits, OutfitPixels,
                         ::testing::Values(OutfitCase{"outfit-layers.iv", "Dress", true},
                                           OutfitCase{"outfit-skirt.iv", "Skirt", false}),
                         [](const auto& outfit) { return std::string(outfit.param.outer); });

}  // namespace test_OutfitPixels
