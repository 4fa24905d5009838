// Garments draped over garments (paper §6's layers): a ClothEngine's body may be a
// CollisionGroup of the Mannequin and an inner garment's GarmentSurface, whose points
// are the inner engine's output. The outfit of scenes/outfit-layers.iv (the T-shirt
// under the dress; the T-shirt under the skirt in outfit-skirt.iv) drapes inside out and comes to rest with no dress
// node behind the T-shirt's surface and no node of either inside the body's volumes; bad groups and surfaces are one
// line naming the node, the entry or field and the value.
#include <Inventor/fields/SoMFVec3f.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "nodes/SceneSearch.h"
#include "nodes/body/CollisionBody.h"
#include "nodes/body/CollisionGroup.h"
#include "nodes/cloth/GarmentSurface.h"
#include "sim/collision/Collider.h"
#include "sim/drape/DrapeReport.h"
#include "support/SceneTestSupport.h"
#include "support/ShippedGarmentScene.h"

namespace test_LayeredGarments {

using namespace figment::test;

namespace {

ClothEngine* engineNamed(SoNode* root, const char* name) {
  for (ClothEngine* engine : figment::findClothEngines(root))
    if (engine->getName() == name) return engine;
  return nullptr;
}

std::vector<figment::Vec3> drape(ClothEngine& engine) {
  SoMFVec3f positions;
  positions.connectFrom(&engine.positions);
  positions.evaluate();
  std::vector<figment::Vec3> x;
  for (int i = 0; i < positions.getNum(); ++i) x.emplace_back(positions[i][0], positions[i][1], positions[i][2]);
  return x;
}

// Nodes of `x` deeper than `depth` inside `collider` (m).
int deeperThan(const figment::Collider& collider, const std::vector<figment::Vec3>& x, double depth) {
  int count = 0;
  figment::Contact c;
  for (const figment::Vec3& p : x) count += collider.contact(p, 0.0, 0.05, c) && c.distance < -depth;
  return count;
}

}  // namespace

// An outfit of the T-shirt (ShirtDrape) under an outer garment, draped and checked.
struct DrapedOutfit {
  explicit DrapedOutfit(const char* file, const char* outerEngine) : scene(file) {
    if (!scene.root()) return;
    shirt = engineNamed(scene.root(), "ShirtDrape");
    outer = engineNamed(scene.root(), outerEngine);
    if (!shirt || !outer) return;
    outerAtRest = drape(*outer);
    auto* group = dynamic_cast<CollisionGroup*>(outer->body.getValue());
    surface = group && group->layers.getNum() == 1 ? dynamic_cast<GarmentSurface*>(group->layers[0]) : nullptr;
    if (!surface) return;
    for (int i = 0; i < surface->point.getNum(); ++i)
      shirtAtRest.emplace_back(surface->point[i][0], surface->point[i][1], surface->point[i][2]);
    volumes = figment::asCollisionBody(group->body.getValue())->bodyCollider().get();
  }

  // Asking for the outer garment drapes the T-shirt first (its body needs the T-shirt's
  // surface), once; both rest; no outer node lies behind the T-shirt's cloth (inside its
  // 2 mm by more than 1 mm: the penalty contacts' springs give a little); no node of
  // either lies in the body.
  void expectRestingInLayers() const {
    ASSERT_TRUE(shirt && outer && surface && volumes);
    ASSERT_EQ(outer->lastError(), "");
    EXPECT_EQ(shirt->evaluationCount(), 1) << "the T-shirt drapes once, before the outer garment";
    EXPECT_TRUE(shirt->lastRun().run.atRest);
    EXPECT_TRUE(outer->lastRun().run.atRest) << outer->lastRun().run.iterations << " steps";
    ASSERT_EQ(shirtAtRest.size(), static_cast<size_t>(shirt->restPoints.getNum()));
    EXPECT_EQ(deeperThan(*surface->bodyCollider(), outerAtRest, thickness() - 0.001), 0);
    EXPECT_EQ(deeperThan(*volumes, outerAtRest, 0.001), 0);
    EXPECT_EQ(deeperThan(*volumes, shirtAtRest, 0.001), 0);
  }
  double thickness() const { return surface->thickness.getValue(); }

  ShippedGarmentScene scene;
  ClothEngine* shirt = nullptr;
  ClothEngine* outer = nullptr;
  GarmentSurface* surface = nullptr;
  const figment::Collider* volumes = nullptr;
  std::vector<figment::Vec3> outerAtRest, shirtAtRest;
};

TEST(LayeredGarments, TheDressOverTheTShirtRestsOutsideItAndTheBody) {
  const DrapedOutfit outfit("outfit-layers.iv", "DressDrape");
  outfit.expectRestingInLayers();
  ASSERT_TRUE(outfit.volumes);
  // It started clean over the T-shirt (cut round the body alone, a quarter of its nodes lay
  // under the shirt's drape): moved out over it before the first step, and no warning.
  EXPECT_GT(outfit.outer->lastRun().startedOverLayers, int(outfit.outerAtRest.size()) / 10);
  EXPECT_EQ(outfit.outer->lastRun().garmentWarning, "");
  // And the T-shirt held the dress out: over the chest the dress lies farther from the
  // body than the dress alone does (its 6 mm clearance) by about the shirt's standing off.
  int lifted = 0;
  figment::Contact c;
  for (const figment::Vec3& p : outfit.outerAtRest)
    lifted += !outfit.volumes->contact(p, 0.0, 0.05, c) && c.distance > 0.006 + outfit.thickness();
  EXPECT_GT(lifted, static_cast<int>(outfit.outerAtRest.size()) / 4);
}

TEST(LayeredGarments, TheSkirtOverTheTShirtsHemRestsOutsideItAndTheBody) {
  // The paper's Figure 6.2 (scenes/outfit-skirt.iv): the T-shirt tucked into the skirt.
  const DrapedOutfit outfit("outfit-skirt.iv", "SkirtDrape");
  outfit.expectRestingInLayers();
  ASSERT_TRUE(outfit.surface);
  // The skirt's waist rests on the T-shirt's hem: some skirt nodes lie within a
  // centimetre of the T-shirt's surface (its contacts held them out).
  int onTheShirt = 0;
  figment::Contact c;
  for (const figment::Vec3& p : outfit.outerAtRest)
    onTheShirt += outfit.surface->bodyCollider()->contact(p, 0.01, 0.05, c);
  EXPECT_GT(onTheShirt, 20);
}

TEST(LayeredGarments, ABadGroupOrSurfaceIsOneLineNamingIt) {
  initCoin();
  const std::string sheet = "restPoints [ 0 1 0, 0.1 1 0, 0 1 0.1 ]  coordIndex [ 0 1 2 -1 ]  maxTime 0.01\n";
  const struct {
    const char* body;
    const char* expected;
  } cases[] = {
      {"CollisionGroup { }", "CollisionGroup: body and layers are empty"},
      {"CollisionGroup { layers [ Cube { } ] }", "CollisionGroup: layers[0] is Cube, not a collision body"},
      {"CollisionGroup { body Cube { } }", "CollisionGroup: body is Cube, not a collision body"},
      {"CollisionGroup { layers [ GarmentSurface { point [ 0 0 0, 1 0 0, 0 1 0 ]  coordIndex [ 0 1 2 -1 ]  "
       "thickness -1 } ] }",
       "GarmentSurface: thickness = -1"},
      {"CollisionGroup { layers [ GarmentSurface { point [ 0 0 0, 1 0 0 ]  coordIndex [ 0 1 5 -1 ] } ] }",
       "coordIndex[2] = 5 is not a vertex: point has 2 points"},
  };
  for (const auto& bad : cases) {
    CapturedErrors errors;
    SceneRoot root =
        readString(std::string("#Inventor V2.1 ascii\nSeparator { Coordinate3 { point = DEF E ClothEngine { ") + sheet +
                   " body " + bad.body + " } . positions } }\n");
    ASSERT_TRUE(root) << bad.body << errors.all();
    ClothEngine* engine = engineNamed(root.get(), "E");
    ASSERT_NE(engine, nullptr);
    drape(*engine);
    EXPECT_NE(engine->lastError().find(bad.expected), std::string::npos) << engine->lastError();
    EXPECT_EQ(std::count(engine->lastError().begin(), engine->lastError().end(), '\n'), 0);
  }
}

}  // namespace test_LayeredGarments
