// The start-up every front end makes: after initHeadless() Coin is initialised, knows FIGMENT's
// node kit, prints its messages in one line after the front end's prefix and renders
// off-screen with no display.
#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoDB.h>
#include <Inventor/SoOffscreenRenderer.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/nodes/SoBaseColor.h>
#include <Inventor/nodes/SoCube.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoOrthographicCamera.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "headless/InitHeadless.h"

namespace {

constexpr const char* kPrefix = "figment-test: warning: ";

std::string printedWarning() {
  testing::internal::CaptureStderr();
  SoDebugError::postWarning("Somewhere::method", "first part\nsecond part");
  return testing::internal::GetCapturedStderr();
}

TEST(InitHeadless, StartsCoinWithFigmentsNodeKit) {
  figment::initHeadless(kPrefix);
  EXPECT_TRUE(SoDB::isInitialized());
  for (const char* name : {"ClothEngine", "MeshFile", "ClothingLayer", "Mannequin"})
    EXPECT_FALSE(SoType::fromName(name).isBad()) << name;
}

TEST(InitHeadless, PrintsCoinsMessagesInOneLineAfterThePrefixOfTheFirstCall) {
  figment::initHeadless(kPrefix);
  figment::initHeadless("another program: ");  // changes nothing: the first call decides
  const std::string printed = printedWarning();
  EXPECT_EQ(printed.rfind(kPrefix, 0), 0u) << printed;
  EXPECT_EQ(printed.find('\n'), printed.size() - 1) << printed;
}

TEST(InitHeadless, RendersOffScreenWithNoDisplay) {
  unsetenv("DISPLAY");  // before Coin's first context: OSMesa needs none
  figment::initHeadless(kPrefix);
  SoSeparator* root = new SoSeparator;
  root->ref();
  auto* camera = new SoOrthographicCamera;
  auto* model = new SoLightModel;
  model->model = SoLightModel::BASE_COLOR;  // the colour as written, no lighting
  auto* colour = new SoBaseColor;
  colour->rgb.setValue(1, 0, 0);
  root->addChild(camera);
  root->addChild(model);
  root->addChild(colour);
  root->addChild(new SoCube);
  const SbViewportRegion viewport(16, 16);
  camera->viewAll(root, viewport, 2.0f);  // the cube fills the middle, the corners stay clear
  SoOffscreenRenderer renderer(viewport);
  renderer.setBackgroundColor(SbColor(0, 0, 0));
  ASSERT_TRUE(renderer.render(root));
  const unsigned char* pixels = renderer.getBuffer();
  ASSERT_NE(pixels, nullptr);
  const unsigned char* middle = pixels + 3 * (8 * 16 + 8);
  EXPECT_EQ(middle[0], 255);
  EXPECT_EQ(middle[1], 0);
  EXPECT_EQ(middle[2], 0);
  EXPECT_EQ(pixels[0], 0);  // the control: a corner is the background
  root->unref();
}

}  // namespace
