// SceneRenderer's supersampling: drawn at k times the size and box-filtered down, an
// edge gets the colours between its two sides, and only those; drawn once a pixel,
// none.

#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoFaceSet.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoOrthographicCamera.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "headless/InitHeadless.h"
#include "session/SceneRenderer.h"

using figment::session::ImageSize;
using figment::session::SceneRenderer;

namespace {

constexpr ImageSize kSize{120, 90};
constexpr int kGrey = 204;  // SceneRenderer::background(), 0.8

// A flat red triangle with two slanted edges on the grey background: an orthographic
// view 4 x 3 units wide, looking down -z. Referenced; the caller unrefs it.
SoSeparator* redTriangle() {
  auto* root = new SoSeparator;
  root->ref();
  auto* camera = new SoOrthographicCamera;
  camera->position.setValue(0.0f, 0.0f, 5.0f);
  camera->height = 3.0f;
  camera->aspectRatio = float(kSize.width) / float(kSize.height);
  camera->viewportMapping = SoCamera::LEAVE_ALONE;
  root->addChild(camera);
  auto* flat = new SoLightModel;
  flat->model = SoLightModel::BASE_COLOR;
  root->addChild(flat);
  auto* red = new SoMaterial;
  red->diffuseColor.setValue(1.0f, 0.0f, 0.0f);
  root->addChild(red);
  auto* corners = new SoCoordinate3;
  const SbVec3f points[] = {{-1.3f, -1.1f, 0.0f}, {1.4f, -0.9f, 0.0f}, {0.1f, 1.2f, 0.0f}};
  corners->point.setValues(0, 3, points);
  root->addChild(corners);
  root->addChild(new SoFaceSet);
  return root;
}

struct EdgeCount {
  int red = 0, grey = 0, between = 0, elsewhere = 0;
  double redCoverage = 0.0;  // the sum over the pixels of how red each is, 0 to 1
};

// Sorts every pixel of `renderer`'s image: red, grey, a mix of the two (each channel
// on the line from grey to red, within 3 levels: a box filter of red and grey samples
// gives nothing else) or anything else.
EdgeCount countEdge(const SceneRenderer& renderer) {
  EdgeCount count;
  const unsigned char* rgb = renderer.pixels();
  for (int i = 0; i < kSize.width * kSize.height; ++i, rgb += 3) {
    const double redness = (rgb[0] - kGrey) / double(255 - kGrey);  // 0 grey, 1 red
    const double fromGreen = (kGrey - rgb[1]) / double(kGrey), fromBlue = (kGrey - rgb[2]) / double(kGrey);
    const bool onTheLine = std::abs(redness - fromGreen) * kGrey < 3.0 && std::abs(redness - fromBlue) * kGrey < 3.0 &&
                           redness > -0.05 && redness < 1.05;
    if (!onTheLine)
      ++count.elsewhere;
    else if (rgb[0] >= 253 && rgb[1] <= 2)
      ++count.red;
    else if (std::abs(rgb[0] - kGrey) <= 2 && std::abs(rgb[1] - kGrey) <= 2)
      ++count.grey;
    else
      ++count.between;
    if (onTheLine) count.redCoverage += std::min(1.0, std::max(0.0, redness));
  }
  return count;
}

EdgeCount renderTriangle(int supersample) {
  figment::initHeadless();
  SoSeparator* scene = redTriangle();
  SceneRenderer renderer(kSize, supersample);
  EXPECT_EQ(renderer.render(scene), "");
  scene->unref();
  EXPECT_EQ(renderer.supersample(), supersample);
  return renderer.pixels() ? countEdge(renderer) : EdgeCount{};
}

}  // namespace

TEST(SceneRenderer, OneSampleAPixelGivesNoColoursBetween) {
  const EdgeCount count = renderTriangle(1);
  EXPECT_EQ(count.between, 0);
  EXPECT_EQ(count.elsewhere, 0);
  EXPECT_GT(count.red, 1000);
  EXPECT_GT(count.grey, 1000);
}

TEST(SceneRenderer, SupersamplingGivesTheEdgeColoursBetweenAndNoOthers) {
  const EdgeCount one = renderTriangle(1);
  for (int k : {2, 3, 4}) {
    const EdgeCount count = renderTriangle(k);
    // The triangle's outline crosses about 230 pixels; most of them mix (fewer with
    // fewer samples: 147 at k = 2, where the nearly level base lands on whole samples).
    EXPECT_GT(count.between, 100) << "k " << k;
    EXPECT_EQ(count.elsewhere, 0) << "k " << k << ": no colour off the line from grey to red";
    // The same triangle: its area in pixels, within the outline's rounding.
    EXPECT_NEAR(count.redCoverage, one.redCoverage, 0.01 * one.redCoverage) << "k " << k;
  }
}

TEST(SceneRenderer, SupersamplingStaysWithinTheLargestImage) {
  EXPECT_EQ(SceneRenderer::supersampleWithin({800, 600}, 3, 16384, 16384), 3);
  EXPECT_EQ(SceneRenderer::supersampleWithin({6000, 1000}, 3, 16384, 16384), 2);
  EXPECT_EQ(SceneRenderer::supersampleWithin({800, 600}, 3, 1000, 1000), 1);
  EXPECT_EQ(SceneRenderer::supersampleWithin({20000, 100}, 3, 16384, 16384), 1) << "never below one sample";
  // No maximum known (0): Coin's 16-bit viewport still bounds it.
  EXPECT_EQ(SceneRenderer::supersampleWithin({16000, 100}, 3, 0, 0), 2);
  EXPECT_EQ(SceneRenderer::supersampleWithin({800, 600}, 0, 16384, 16384), 1);
}
