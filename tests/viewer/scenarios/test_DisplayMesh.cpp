// ClothingLayer's display mesh (displaySubdivision, issue 29) in a picture that can fail: a
// coarse surface's outline turns in fewer, smaller kinks. (On the draped dress, the hybrid
// invariant and skin through the cloth: test_HybridNeverHidesCloth.)
#include <Inventor/nodes/SoBaseColor.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "headless/InitHeadless.h"
#include "nodes/render/ClothingLayer.h"
#include "session/SceneStaging.h"
#include "support/Pixels.h"
#include "support/RenderedImage.h"
#include "support/TestMeshes.h"

using namespace figment::session;
using figment::test::Image;

namespace {

class DisplayMesh : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { figment::initHeadless(); }
};

// A coarse ball (12 vertices round its equator) as a blue ClothingLayer in flat colour.
SoSeparator* coarseBall(int displaySubdivision) {
  const figment::TriangleMesh ball = figment::meshes::sphere(0.5, 12, 8);
  auto* scene = new SoSeparator;
  auto* flat = new SoLightModel;
  flat->model = SoLightModel::BASE_COLOR;
  auto* blue = new SoBaseColor;
  blue->rgb.setValue(0.0f, 0.0f, 1.0f);
  auto* coordinates = new SoCoordinate3;
  for (size_t i = 0; i < ball.vertices.size(); ++i) {
    const figment::Vec3& p = ball.vertices[i];
    coordinates->point.set1Value(int(i), float(p.x()), float(p.y()), float(p.z()));
  }
  auto* layer = new ClothingLayer;
  for (const figment::Triangle& t : ball.triangles)
    for (int corner : {t[0], t[1], t[2], -1}) layer->coordIndex.set1Value(layer->coordIndex.getNum(), corner);
  layer->displaySubdivision = displaySubdivision;
  for (SoNode* node : std::vector<SoNode*>{flat, blue, coordinates, layer}) scene->addChild(node);
  return scene;
}

// The largest turn (degrees) of the blue region's outline, traced as the farthest blue pixel
// from the picture's centre at each degree round it, between chords 8 degrees long.
double largestOutlineTurn(const Image& image) {
  std::vector<std::array<double, 2>> outline;
  const double cx = 0.5 * image.width, cy = 0.5 * image.height;
  for (int degree = 0; degree < 360; ++degree) {
    const double a = degree * M_PI / 180.0;
    double farthest = 0.0;
    for (double r = 0.0; r < 0.5 * image.width; r += 0.25) {
      const int x = int(cx + r * std::cos(a)), y = int(cy + r * std::sin(a));
      if (image.is(y * image.width + x, figment::test::kBlue)) farthest = r;
    }
    outline.push_back({cx + farthest * std::cos(a), cy + farthest * std::sin(a)});
  }
  constexpr int kChord = 8;
  double most = 0.0;
  for (int k = 0; k < 360; ++k) {
    const auto& p = outline[k];
    const auto& q = outline[(k + kChord) % 360];
    const auto& r = outline[(k + 2 * kChord) % 360];
    const double in = std::atan2(q[1] - p[1], q[0] - p[0]), out = std::atan2(r[1] - q[1], r[0] - q[0]);
    double turn = std::abs(out - in) * 180.0 / M_PI;
    most = std::max(most, std::min(turn, 360.0 - turn));
  }
  return most;
}

}  // namespace

// Seen from its pole the ball's outline is its equator: a 12-gon, which turns 30 degrees at
// each corner and not at all between them; two levels of the display mesh round it (48
// vertices, 7.5 degrees each, as far as the raster shows).
TEST_F(DisplayMesh, AnOutlineTurnsInSmallerKinks) {
  constexpr ImageSize kSize{400, 400};
  double turns[2];
  for (int levels : {0, 2}) {
    SoSeparator* root = stageScene(coarseBall(levels), kSize, ViewDirection{0.0, 90.0});
    root->ref();
    const Image image = figment::test::renderedImage(root, kSize);
    root->unref();
    ASSERT_GT(image.count(figment::test::kBlue), 20000);
    turns[levels / 2] = largestOutlineTurn(image);
  }
  EXPECT_GT(turns[0], 20.0) << "the 12-gon's corners";
  EXPECT_LT(turns[1], 0.5 * turns[0]);
  RecordProperty("coarseDegrees", std::to_string(turns[0]));
  RecordProperty("displayDegrees", std::to_string(turns[1]));
}
