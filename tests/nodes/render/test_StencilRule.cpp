// The stencil rule for one view: a body part in front of a garment writes the stencil and
// masks the garment; a part behind it, or beside it on screen, does neither. A square garment
// at z = 0 seen from +z.
#include <Inventor/SbViewportRegion.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include <string>

#include "nodes/render/ClothingLayer.h"
#include "nodes/render/StencilRule.h"
#include "nodes/render/StencilSeparator.h"
#include "support/SceneTestSupport.h"

using namespace figment::test;

namespace {

// A 1 m square garment at z = 0 and three 10 cm cubes: in front of it, behind it, and in front
// but 3 m to the side.
SceneRoot scene() {
  return readString(
      "#Inventor V2.1 ascii\nSeparator {\n"
      "  Separator { Coordinate3 { point [ -0.5 -0.5 0, 0.5 -0.5 0, 0.5 0.5 0, -0.5 0.5 0 ] }\n"
      "    DEF Shirt ClothingLayer { coordIndex [ 0, 1, 2, -1, 0, 2, 3, -1 ] } }\n"
      "  DEF Front StencilSeparator { Translation { translation 0 0 0.3 } Cube { width 0.1 height 0.1 depth 0.1 } }\n"
      "  DEF Back StencilSeparator { Translation { translation 0 0 -0.3 } Cube { width 0.1 height 0.1 depth 0.1 } }\n"
      "  DEF Aside StencilSeparator { Translation { translation 3 0 0.3 } Cube { width 0.1 height 0.1 depth 0.1 } }\n"
      "}\n");
}

TEST(StencilRule, APartInFrontOfTheGarmentWritesAndMasksIt) {
  initCoin();
  SceneRoot root = scene();
  ASSERT_TRUE(root);
  auto* camera = new SoPerspectiveCamera;
  camera->ref();
  camera->position.setValue(0, 0, 5);  // looking down -z at the square
  const SbViewportRegion viewport(200, 200);
  const figment::StencilDecision decision = figment::decideStencil(root.get(), viewport, camera->getViewVolume(1.0f));
  const SoNode* shirt = find<ClothingLayer>(root.get(), "Shirt");
  EXPECT_TRUE(decision.writes(find<StencilSeparator>(root.get(), "Front")));
  EXPECT_FALSE(decision.writes(find<StencilSeparator>(root.get(), "Back")));
  EXPECT_FALSE(decision.writes(find<StencilSeparator>(root.get(), "Aside")));
  EXPECT_TRUE(decision.masks(shirt));
  EXPECT_EQ(decision.writers.size(), 1u);
  camera->unref();
}

TEST(StencilRule, SeenFromBehindThePartsChangePlaces) {
  initCoin();
  SceneRoot root = scene();
  ASSERT_TRUE(root);
  auto* camera = new SoPerspectiveCamera;
  camera->ref();
  camera->position.setValue(0, 0, -5);
  camera->orientation.setValue(SbVec3f(0, 1, 0), float(M_PI));  // looking down +z
  const figment::StencilDecision decision =
      figment::decideStencil(root.get(), SbViewportRegion(200, 200), camera->getViewVolume(1.0f));
  EXPECT_TRUE(decision.writes(find<StencilSeparator>(root.get(), "Back")));
  EXPECT_FALSE(decision.writes(find<StencilSeparator>(root.get(), "Front")));
  camera->unref();
}

TEST(StencilRule, NoGarmentNoDecision) {
  initCoin();
  SceneRoot root = readString("#Inventor V2.1 ascii\nSeparator { StencilSeparator { Cube { } } }\n");
  ASSERT_TRUE(root);
  auto* camera = new SoPerspectiveCamera;
  camera->ref();
  camera->position.setValue(0, 0, 5);
  const figment::StencilDecision decision =
      figment::decideStencil(root.get(), SbViewportRegion(100, 100), camera->getViewVolume(1.0f));
  EXPECT_TRUE(decision.writers.empty());
  EXPECT_TRUE(decision.masked.empty());
  camera->unref();
}

}  // namespace
