// The hybrid renderer (paper §5) in a plain Coin program: no viewer code, only Coin,
// FIGMENT's node library and OSMesa. It reads scenes/dress.iv (through a wrapper file
// that places a camera at azimuth 60°, elevation 10°), renders it with
// SoOffscreenRenderer, and gets exactly the pixels figment-view writes for the same
// file. From that side the near arm is in front of the dress: the stencil rule, run
// inside the render, keeps its pixels.
#include <Inventor/SbImage.h>
#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/SoOffscreenRenderer.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/actions/SoWriteAction.h>
#include <Inventor/nodes/SoDirectionalLight.h>
#include <Inventor/nodes/SoFile.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include "headless/OsmesaForCoin.h"
#include "nodes/Init.h"
#include "nodes/render/StencilRuleElement.h"
#include "support/TempDir.h"

namespace {

constexpr short kWidth = 360, kHeight = 420;  // docs/images' size for Figure 5.3

// RGB, bottom row first, as SoOffscreenRenderer reads it back.
using Pixels = std::vector<unsigned char>;

// scenes/dress.iv seen from azimuth 60°, elevation 10° (degrees about the y axis from
// +z, then up), 3 m from about the middle of the dress, written as an .iv file.
std::string writeWrapper(const figment::test::TempDir& dir) {
  const float az = 60.0f * std::numbers::pi_v<float> / 180.0f, el = 10.0f * std::numbers::pi_v<float> / 180.0f;
  const SbVec3f target(0.0f, 1.05f, 0.0f);
  auto* camera = new SoPerspectiveCamera;
  camera->position = target + 3.0f * SbVec3f(std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el));
  camera->pointAt(target, SbVec3f(0.0f, 1.0f, 0.0f));
  camera->nearDistance = 1.5f;
  camera->farDistance = 4.5f;
  // A light of its own, so figment-view (which looks for lights outside File nodes
  // only) adds no headlight: both renders then light the scene alike.
  auto* light = new SoDirectionalLight;
  light->direction = -camera->position.getValue();
  light->intensity = 0.3f;
  auto* dress = new SoFile;
  dress->name = (std::string(FIGMENT_SOURCE_DIR) + "/scenes/dress.iv").c_str();
  SoSeparator* root = new SoSeparator;
  root->ref();
  root->addChild(camera);
  root->addChild(light);
  root->addChild(dress);
  const std::string path = (dir.path() / "dress-60-10.iv").string();
  SoOutput out;
  EXPECT_TRUE(out.openFile(path.c_str()));
  SoWriteAction(&out).apply(root);
  out.closeFile();
  root->unref();
  return path;
}

// Reads `path` as any Coin program would; the caller unrefs the root.
SoSeparator* readScene(const std::string& path) {
  SoInput in;
  EXPECT_TRUE(in.openFile(path.c_str()));
  SoSeparator* root = SoDB::readAll(&in);
  EXPECT_NE(root, nullptr);
  if (root) root->ref();
  return root;
}

// Renders `root` with SoOffscreenRenderer (figment-view's grey behind).
Pixels renderWithCoin(SoNode* root, bool keepStencilFields = false) {
  SoOffscreenRenderer renderer(SbViewportRegion(kWidth, kHeight));
  renderer.setComponents(SoOffscreenRenderer::RGB);
  renderer.setBackgroundColor(SbColor(0.8f, 0.8f, 0.8f));
  if (keepStencilFields) figment::keepStencilFields(*renderer.getGLRenderAction(), true);
  EXPECT_TRUE(renderer.render(root));
  const unsigned char* rgb = renderer.getBuffer();
  return Pixels(rgb, rgb + 3 * kWidth * kHeight);
}

// figment-view's picture of `scene` (its own camera and lights), as RGB bottom-up.
Pixels renderWithFigmentView(const figment::test::TempDir& dir, const std::string& scene) {
  const std::string png = (dir.path() / "figment-view.png").string();
  const std::string command = std::string("'") + FIGMENT_VIEW_EXECUTABLE + "' '" + scene + "' -o '" + png +
                              "' --size " + std::to_string(kWidth) + "x" + std::to_string(kHeight) +
                              " --supersample 1";  // one sample a pixel, as the plain program draws
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  SbImage image;
  EXPECT_TRUE(image.readFile(png.c_str())) << png;
  SbVec2s size;
  int bytesPerPixel = 0;
  const unsigned char* data = image.getValue(size, bytesPerPixel);
  EXPECT_EQ(size, SbVec2s(kWidth, kHeight));
  if (!data || size != SbVec2s(kWidth, kHeight) || bytesPerPixel < 3) return {};
  Pixels pixels;
  for (int i = 0; i < kWidth * kHeight; ++i) {
    const unsigned char* pixel = data + i * bytesPerPixel;
    pixels.insert(pixels.end(), pixel, pixel + 3);
  }
  return pixels;
}

// The orange-brown skin, lit or in shade (the default scene's check).
int skinPixels(const Pixels& rgb) {
  int skin = 0;
  for (size_t i = 0; i + 2 < rgb.size(); i += 3) {
    const int r = rgb[i], g = rgb[i + 1], b = rgb[i + 2];
    skin += !(b > r + 30 && b > g + 15) && r > b + 25 && r >= g;
  }
  return skin;
}

int differingPixels(const Pixels& a, const Pixels& b) {
  int differ = 0;
  for (size_t i = 0; i + 2 < std::min(a.size(), b.size()); i += 3)
    differ += a[i] != b[i] || a[i + 1] != b[i + 1] || a[i + 2] != b[i + 2];
  return differ;
}

class PlainCoinRendering : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    figment::useOsmesaForCoin();  // before SoDB::init()
    figment::init();
  }
};

}  // namespace

TEST_F(PlainCoinRendering, TheDressFromTheSideHasFigmentViewsPixels) {
  const figment::test::TempDir dir;
  const std::string scene = writeWrapper(dir);
  SoSeparator* root = readScene(scene);
  ASSERT_NE(root, nullptr);
  const Pixels coin = renderWithCoin(root);  // drapes the dress on the way
  const Pixels view = renderWithFigmentView(dir, scene);
  ASSERT_EQ(coin.size(), size_t(3 * kWidth * kHeight));
  ASSERT_EQ(view.size(), coin.size());
  EXPECT_EQ(differingPixels(coin, view), 0);

  // The stencil is at work: with the scene's own fields (nothing writes the stencil)
  // the dress paints over the near arm, which the rule keeps in front.
  const Pixels fields = renderWithCoin(root, true);
  RecordProperty("skin_pixels_rule", skinPixels(coin));
  RecordProperty("skin_pixels_fields", skinPixels(fields));
  EXPECT_GT(skinPixels(coin), skinPixels(fields) + 200)
      << "rule " << skinPixels(coin) << ", fields " << skinPixels(fields);
  root->unref();
}
