// Headless rendering through OSMesa draws what it should, including the silent trap of
// design.md: without glXGetProcAddress forwarded to OSMesa, face sets drawn through
// vertex arrays come out blank with no error.

#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoOrthographicCamera.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include "headless/InitHeadless.h"
#include "session/SceneRenderer.h"
#include "session/SceneStaging.h"

using namespace figment::session;

namespace {

constexpr int kWidth = 400, kHeight = 300;

// An orthographic view 4 x 3 units wide, 100 pixels per unit, looking down -z.
SoSeparator* flatRedScene() {
  figment::initHeadless();
  auto* root = new SoSeparator;
  auto* camera = new SoOrthographicCamera;
  camera->position.setValue(0.0f, 0.0f, 5.0f);
  camera->height = 3.0f;
  camera->aspectRatio = float(kWidth) / kHeight;
  camera->viewportMapping = SoCamera::LEAVE_ALONE;
  camera->nearDistance = 1.0f;
  camera->farDistance = 10.0f;
  root->addChild(camera);
  auto* lightModel = new SoLightModel;
  lightModel->model = SoLightModel::BASE_COLOR;  // flat colour: every covered pixel is pure red
  root->addChild(lightModel);
  auto* material = new SoMaterial;
  material->diffuseColor.setValue(1.0f, 0.0f, 0.0f);
  root->addChild(material);
  return root;
}

// A grid of nx x ny quads (2 triangles each) covering [x0, x1] x [y0, y1] at z = 0.
void addGrid(SoSeparator* root, int nx, int ny, float x0, float y0, float x1, float y1) {
  auto* coords = new SoCoordinate3;
  coords->point.setNum((nx + 1) * (ny + 1));
  SbVec3f* p = coords->point.startEditing();
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) *p++ = SbVec3f(x0 + (x1 - x0) * i / nx, y0 + (y1 - y0) * j / ny, 0.0f);
  coords->point.finishEditing();
  auto* faces = new SoIndexedFaceSet;
  faces->coordIndex.setNum(nx * ny * 8);
  int32_t* c = faces->coordIndex.startEditing();
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = j * (nx + 1) + i, b = a + 1, d = a + nx + 1, e = d + 1;
      for (int v : {a, b, e, -1, a, e, d, -1}) *c++ = v;
    }
  faces->coordIndex.finishEditing();
  root->addChild(coords);
  root->addChild(faces);
}

int countRed(const SceneRenderer& renderer) {
  const unsigned char* rgb = renderer.pixels();
  int count = 0;
  for (int i = 0; i < kWidth * kHeight; ++i, rgb += 3)
    if (rgb[0] > 250 && rgb[1] < 5 && rgb[2] < 5) ++count;
  return count;
}

int render(SoSeparator* scene) {
  figment::initHeadless();
  scene->ref();
  SceneRenderer renderer({kWidth, kHeight});
  const std::string error = renderer.render(scene);
  scene->unref();
  EXPECT_EQ(error, "");
  return error.empty() ? countRed(renderer) : -1;
}

}  // namespace

TEST(OffscreenRendering, SmallQuadCoversItsPixels) {
  SoSeparator* scene = flatRedScene();
  addGrid(scene, 1, 1, -1.0f, -0.75f, 1.0f, 0.75f);  // 200 x 150 pixels
  EXPECT_NEAR(render(scene), 200 * 150, 0.01 * 200 * 150);
}

TEST(OffscreenRendering, LargeFlatFaceSetCoversItsPixels) {
  // 50,000 triangles in BASE_COLOR: drawn through vertex arrays, the path that comes
  // out blank when Coin's extension look-up bypasses OSMesa.
  SoSeparator* scene = flatRedScene();
  addGrid(scene, 250, 100, -1.0f, -0.75f, 1.0f, 0.75f);
  EXPECT_NEAR(render(scene), 200 * 150, 0.01 * 200 * 150);
}

TEST(OffscreenRendering, BackgroundIsNeutralGrey) {
  figment::initHeadless();
  SoSeparator* scene = flatRedScene();
  scene->ref();
  SceneRenderer renderer({kWidth, kHeight});
  ASSERT_EQ(renderer.render(scene), "");
  scene->unref();
  const unsigned char* corner = renderer.pixels();
  EXPECT_EQ(corner[0], corner[1]);
  EXPECT_EQ(corner[1], corner[2]);
  EXPECT_NEAR(corner[0], 0.8 * 255, 1.0);
}
