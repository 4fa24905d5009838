// Paper §5 in pictures that can fail: scenes/hybrid/*.iv rendered through OSMesa with
// FIGMENT's nodes and with the depth buffer alone (the -plain files), pixels counted by
// flat colour.
#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoDrawStyle.h>
#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "guard/SceneFile.h"
#include "headless/InitHeadless.h"
#include "nodes/render/ClothingLayer.h"
#include "nodes/render/DepthSortedGroup.h"
#include "nodes/render/StencilRule.h"
#include "nodes/render/StencilSeparator.h"
#include "session/SceneRenderer.h"
#include "session/SceneStaging.h"
#include "support/Pixels.h"
#include "support/RenderedImage.h"
#include "support/TempDir.h"
#include "viewer/DepthBufferOnly.h"

namespace test_HybridRendering {

using namespace figment::session;
using namespace figment::viewer;
using figment::test::Image;

namespace {

constexpr ImageSize kSize{240, 240};

// A scene from scenes/hybrid, staged for one view, that can hide named parts.
class View {
 public:
  View(const std::string& name, double azimuth, double elevation = 15.0) {
    std::string error;
    scene_ = figment::guard::readScene(std::string(FIGMENT_SOURCE_DIR) + "/scenes/hybrid/" + name + ".iv", error);
    EXPECT_NE(scene_, nullptr) << error;
    scene_->ref();
    root_ = stageScene(scene_, kSize, ViewDirection{azimuth, elevation});
    root_->ref();
  }
  ~View() {
    root_->unref();
    scene_->unref();
  }
  // A node of this scene by name (scenes loaded side by side reuse names).
  template <typename T>
  T* node(const char* name) const {
    SoPath* path = find(name);
    return path ? dynamic_cast<T*>(path->getTail()) : nullptr;
  }
  // Puts `replacement` where the named node is.
  void replace(const char* name, SoNode* replacement) const {
    SoPath* path = find(name);
    ASSERT_NE(path, nullptr) << name;
    static_cast<SoGroup*>(path->getNodeFromTail(1))->replaceChild(path->getTail(), replacement);
  }
  // Renders with every part but those named hidden (an invisible draw style put first
  // in each part); `keepStencilFields` as figment-view's flag.
  Image render(const std::vector<const char*>& hidden = {}, bool keepStencilFields = false) const {
    std::vector<SoGroup*> parts;
    for (const char* name : hidden) {
      auto* part = node<SoGroup>(name);
      EXPECT_NE(part, nullptr) << name;
      auto* invisible = new SoDrawStyle;
      invisible->style = SoDrawStyle::INVISIBLE;
      part->insertChild(invisible, 0);
      parts.push_back(part);
    }
    Image image = figment::test::renderedImage(root_, kSize, keepStencilFields);
    for (SoGroup* part : parts) part->removeChild(0);
    return image;
  }
  SoSeparator* root() const { return root_; }
  // What the stencil rule decides for this view's camera (as the render does).
  figment::StencilDecision stencilRule() const {
    SoSearchAction search;
    search.setType(SoCamera::getClassTypeId());
    search.apply(root_);
    EXPECT_NE(search.getPath(), nullptr);
    const SbViewportRegion viewport(short(kSize.width), short(kSize.height));
    auto* camera = static_cast<SoCamera*>(search.getPath()->getTail());
    return figment::decideStencil(root_, viewport, camera->getViewVolume(viewport.getViewportAspectRatio()));
  }

 private:
  SoPath* find(const char* name) const {
    search_.reset();
    search_.setName(name);
    search_.setInterest(SoSearchAction::FIRST);
    search_.apply(scene_);
    return search_.getPath();
  }
  mutable SoSearchAction search_;
  SoSeparator* scene_ = nullptr;
  SoSeparator* root_ = nullptr;
};

class HybridRendering : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { figment::initHeadless(); }
};

const std::vector<double> kEightAzimuths = {0, 45, 90, 135, 180, 225, 270, 315};

}  // namespace

TEST_F(HybridRendering, SkinNeverShowsThroughTheCloth) {
  // Inside the cloth's own silhouette: skin pixels with the depth buffer alone (the
  // problem exists), none with ClothingLayer, from 8 directions around.
  int plainTotal = 0;
  for (double azimuth : kEightAzimuths) {
    const View plain("poke-through-plain", azimuth), hybrid("poke-through", azimuth);
    const std::vector<bool> silhouette = hybrid.render({"Ball"}).where(figment::test::kBlue);
    const int plainSkin = plain.render().countWithin(figment::test::kRed, silhouette);
    EXPECT_GT(plainSkin, 0) << "azimuth " << azimuth;
    plainTotal += plainSkin;
    EXPECT_EQ(hybrid.render().countWithin(figment::test::kRed, silhouette), 0) << "azimuth " << azimuth;
  }
  EXPECT_GT(plainTotal, 8 * 100);
}

TEST_F(HybridRendering, TheOuterLayerWinsWhereverItCovers) {
  for (double azimuth : kEightAzimuths) {
    const View plain("layers-plain", azimuth), hybrid("layers", azimuth);
    const std::vector<bool> outer = hybrid.render({"Ball", "Inner"}).where(figment::test::kYellow);
    EXPECT_GT(plain.render().countWithin(figment::test::kBlue, outer), 100) << "azimuth " << azimuth;
    EXPECT_EQ(hybrid.render().countWithin(figment::test::kBlue, outer), 0) << "azimuth " << azimuth;
  }
}

TEST_F(HybridRendering, ASleeveBehindTheShirtStaysBehindItAndShowsInFront) {
  // The sleeve's pixels in a DepthSortedGroup match the depth buffer's (the pieces do not
  // cross), from every side. In a plain Group it is drawn last and, from the front where
  // it lies behind the shirt, shows through it.
  for (double azimuth : kEightAzimuths) {
    const View plain("shirt-plain", azimuth), hybrid("shirt", azimuth);
    const int expected = plain.render().count(figment::test::kMagenta);
    const int sorted = hybrid.render().count(figment::test::kMagenta);
    EXPECT_NEAR(sorted, expected, 0.01 * expected + 20) << "azimuth " << azimuth;
  }
  const View front("shirt", 0.0), back("shirt", 180.0), plainFront("shirt-plain", 0.0);
  EXPECT_GT(back.render().count(figment::test::kMagenta), 2000) << "from behind, the sleeve is in front";
  // The same pieces in a plain Group: the sleeve is drawn over the shirt's front.
  auto* sorted = front.node<DepthSortedGroup>("Shirt");
  ASSERT_NE(sorted, nullptr);
  auto* group = new SoGroup;
  for (int i = 0; i < sorted->getNumChildren(); ++i) group->addChild(sorted->getChild(i));
  sorted->ref();
  front.replace("Shirt", group);
  EXPECT_GT(front.render().count(figment::test::kMagenta), plainFront.render().count(figment::test::kMagenta) + 500);
  sorted->unref();
}

TEST_F(HybridRendering, AForearmInFrontOfTheShirtKeepsItsPixels) {
  const View plain("forearm-plain", 0.0), hybrid("forearm", 0.0);
  const int expected = plain.render().count(figment::test::kGreen);
  ASSERT_GT(expected, 1000);
  // Without the stencil (the fields as written: FALSE) the shirt paints over the forearm.
  EXPECT_LT(hybrid.render({}, true).count(figment::test::kGreen), expected / 2);
  // The rule switches the forearm's stencil and the shirt's mask on for this camera,
  // in the render: the fields keep the values written in the scene.
  EXPECT_GE(hybrid.render().count(figment::test::kGreen), expected);
  auto* forearm = hybrid.node<StencilSeparator>("Forearm");
  ASSERT_NE(forearm, nullptr);
  EXPECT_TRUE(hybrid.stencilRule().writes(forearm));
  EXPECT_FALSE(forearm->writeStencil.getValue());
  auto* shirt = hybrid.node<SoGroup>("Shirt");
  ASSERT_NE(shirt, nullptr);
  auto* layer = dynamic_cast<ClothingLayer*>(shirt->getChild(shirt->getNumChildren() - 1));
  ASSERT_NE(layer, nullptr);
  EXPECT_TRUE(hybrid.stencilRule().masks(layer));
  EXPECT_FALSE(layer->masked.getValue());
  // From behind the forearm is behind the shirt: the rule switches both off, and the
  // forearm stays hidden as with the depth buffer.
  const View behind("forearm", 180.0), plainBehind("forearm-plain", 180.0);
  EXPECT_EQ(behind.render().count(figment::test::kGreen), plainBehind.render().count(figment::test::kGreen));
  EXPECT_FALSE(behind.stencilRule().writes(behind.node<StencilSeparator>("Forearm")));
}

TEST_F(HybridRendering, DepthBufferOnlyDrawsAsThePlainScene) {
  // The swap figment-view --depth-buffer-only makes gives the -plain twin's pixels, and
  // swapping back gives the hybrid picture again.
  for (const char* name : {"poke-through", "shirt", "forearm"}) {
    const View hybrid(name, 30.0), plain((std::string(name) + "-plain").c_str(), 30.0);
    const Image before = hybrid.render();
    {
      DepthBufferOnly swap(hybrid.root());
      swap.use(true);
      EXPECT_EQ(hybrid.render().rgb, plain.render().rgb) << name;
    }
    EXPECT_EQ(hybrid.render().rgb, before.rgb) << name << ": restored";
  }
}

// After a StencilSeparator that writes the stencil and a ClothingLayer drawn over
// everything, a later square behind the cloth is hidden (the depth test is back to
// LESS) and the layer after it is not masked by it (nothing outside the separator
// marked the stencil).
static void expectSeparatorsUndoTheState(bool ruleOffInScene) {
  std::string text = R"(#Inventor V2.1 ascii
Separator {
  LightModel { model BASE_COLOR }
  StencilSeparator { writeStencil TRUE STENCIL_RULE BaseColor { rgb 0 1 0 }
    Coordinate3 { point [ -1 -1 0.5, -0.6 -1 0.5, -0.6 1 0.5, -1 1 0.5 ] } IndexedFaceSet { coordIndex [ 0 1 2 3 -1 ] } }
  Separator { BaseColor { rgb 0 0 1 }
    Coordinate3 { point [ -1 -1 0, 1 -1 0, 1 1 0, -1 1 0 ] } ClothingLayer { coordIndex [ 0 1 2 3 -1 ] masked TRUE STENCIL_RULE } }
  DEF Behind Separator { BaseColor { rgb 1 0 0 }
    Coordinate3 { point [ 0.2 -0.5 -0.5, 0.8 -0.5 -0.5, 0.8 0.5 -0.5, 0.2 0.5 -0.5 ] } IndexedFaceSet { coordIndex [ 0 1 2 3 -1 ] } }
  Separator { BaseColor { rgb 1 1 0 }
    Coordinate3 { point [ 0.2 -1 0.2, 1 -1 0.2, 1 -0.6 0.2, 0.2 -0.6 0.2 ] } IndexedFaceSet { coordIndex [ 0 1 2 3 -1 ] } }
})";
  const std::string rule = ruleOffInScene ? " stencilRule FALSE " : " ";
  for (size_t at; (at = text.find(" STENCIL_RULE ")) != std::string::npos;) text.replace(at, 14, rule);
  figment::test::TempDir dir;
  const std::string path = dir.file("undo.iv", text);
  std::string error;
  SoSeparator* scene = figment::guard::readScene(path, error);
  ASSERT_NE(scene, nullptr) << error;
  scene->ref();
  SoSeparator* root = stageScene(scene, kSize, ViewDirection{0.0, 0.0});
  root->ref();
  SceneRenderer renderer(kSize);
  ASSERT_EQ(renderer.render(root, !ruleOffInScene), "");
  Image image{kSize.width, kSize.height, {}};
  image.rgb.assign(renderer.pixels(), renderer.pixels() + 3 * kSize.width * kSize.height);
  EXPECT_GT(image.count(figment::test::kGreen), 500) << "the marked part stays in front of the masked cloth";
  EXPECT_EQ(image.count(figment::test::kRed), 0) << "the square behind the cloth stays hidden";
  EXPECT_GT(image.count(figment::test::kYellow), 500) << "a later shape in front of the cloth shows";
  EXPECT_GT(image.count(figment::test::kBlue), 1000);
  root->unref();
  scene->unref();
}

TEST_F(HybridRendering, SeparatorsUndoTheDepthAndStencilState) {
  // The scene sets both fields by hand: rendered keeping the scene's fields, and with
  // the rule switched off in the scene itself (stencilRule FALSE), the same way.
  for (const bool inScene : {false, true}) {
    SCOPED_TRACE(inScene ? "stencilRule FALSE in the scene" : "keepStencilFields");
    expectSeparatorsUndoTheState(inScene);
  }
}

}  // namespace test_HybridRendering
