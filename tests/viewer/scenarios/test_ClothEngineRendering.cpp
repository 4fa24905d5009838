// Rendering reads the garment's coordinates but simulates only when an input changed.

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include "headless/InitHeadless.h"
#include "nodes/SceneSearch.h"
#include "nodes/cloth/ClothEngine.h"
#include "session/SceneRenderer.h"
#include "session/SceneStaging.h"

using namespace figment::session;

TEST(ClothEngineRendering, RenderingAgainDoesNotSimulateAgain) {
  figment::initHeadless();
  const std::string text =
      "#Inventor V2.1 ascii\nSeparator {\n"
      "  Coordinate3 { point = DEF Drape ClothEngine {\n"
      "    restPoints [ 0 1 0, 1 1 0, 1 1 1, 0 1 1 ]  coordIndex [ 0 3 2 1 -1 ]  maxTime 0.01\n"
      "  } . positions }\n"
      "  ClothingLayer { coordIndex [ 0 3 2 1 -1 ] }\n"
      "}\n";
  SoInput in;
  in.setBuffer(text.data(), text.size());
  SoSeparator* scene = SoDB::readAll(&in);
  ASSERT_NE(scene, nullptr);
  scene->ref();
  const std::vector<ClothEngine*> engines = figment::findClothEngines(scene);
  ASSERT_EQ(engines.size(), 1u);
  ClothEngine* engine = engines.front();

  SoSeparator* root = stageScene(scene, {64, 64}, ViewDirection{30.0, 20.0});
  root->ref();
  EXPECT_EQ(engine->evaluationCount(), 1) << "staging (its bounding box) simulated";
  SceneRenderer renderer({64, 64});
  ASSERT_EQ(renderer.render(root), "");
  ASSERT_EQ(renderer.render(root), "");
  EXPECT_EQ(engine->evaluationCount(), 1) << "two renders, no new simulation";

  engine->friction = 0.2;
  ASSERT_EQ(renderer.render(root), "");
  EXPECT_EQ(engine->evaluationCount(), 2) << "a changed input simulates on the next render";
  root->unref();
  scene->unref();
}
