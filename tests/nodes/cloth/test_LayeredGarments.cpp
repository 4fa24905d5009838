// Garments draped over garments (paper §6's layers): a ClothEngine's body may be a
// CollisionGroup of the Mannequin and an inner garment's GarmentSurface, whose points
// are the inner engine's output. The outfit of scenes/outfit-layers.iv (the T-shirt
// under the dress) drapes inside out and comes to rest with no dress node behind the
// T-shirt's surface and no node of either inside the body's volumes; bad groups and
// surfaces are one line naming the node, the entry or field and the value.
#include "nodes/SceneSearch.h"
#include "nodes/body/CollisionBody.h"
#include "nodes/body/CollisionGroup.h"
#include "nodes/cloth/GarmentSurface.h"
#include "sim/collision/Collider.h"
#include "support/SceneTestSupport.h"
#include "support/ShippedGarmentScene.h"

#include <Inventor/fields/SoMFVec3f.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

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

TEST(LayeredGarments, TheDressOverTheTShirtRestsOutsideItAndTheBody) {
  const ShippedGarmentScene scene("outfit-layers.iv");
  ASSERT_TRUE(scene.root());
  ClothEngine* shirt = engineNamed(scene.root(), "ShirtDrape");
  ClothEngine* dress = engineNamed(scene.root(), "DressDrape");
  ASSERT_TRUE(shirt && dress);
  // Asking for the dress drapes the T-shirt first: the dress's body needs its surface.
  const std::vector<figment::Vec3> dressAtRest = drape(*dress);
  ASSERT_EQ(dress->lastError(), "");
  EXPECT_EQ(shirt->evaluationCount(), 1) << "the T-shirt drapes once, before the dress";
  EXPECT_TRUE(shirt->lastRun().atRest);
  EXPECT_TRUE(dress->lastRun().atRest) << dress->lastRun().iterations << " steps";

  auto* group = dynamic_cast<CollisionGroup*>(dress->body.getValue());
  ASSERT_NE(group, nullptr);
  ASSERT_EQ(group->layers.getNum(), 1);
  auto* surface = dynamic_cast<GarmentSurface*>(group->layers[0]);
  ASSERT_NE(surface, nullptr);
  std::vector<figment::Vec3> shirtAtRest;  // what the dress draped over
  for (int i = 0; i < surface->point.getNum(); ++i)
    shirtAtRest.emplace_back(surface->point[i][0], surface->point[i][1], surface->point[i][2]);
  ASSERT_EQ(shirtAtRest.size(), static_cast<size_t>(shirt->restPoints.getNum()));
  const figment::Collider& volumes = *figment::asCollisionBody(group->body.getValue())->bodyCollider();
  const figment::Collider& shirtSurface = *surface->bodyCollider();
  // No dress node behind the T-shirt's cloth (inside its 2 mm by more than 1 mm: the
  // penalty contacts' springs give a little), none in the body.
  const double thickness = surface->thickness.getValue();
  EXPECT_EQ(deeperThan(shirtSurface, dressAtRest, thickness - 0.001), 0);
  EXPECT_EQ(deeperThan(volumes, dressAtRest, 0.001), 0);
  EXPECT_EQ(deeperThan(volumes, shirtAtRest, 0.001), 0);
  // And the T-shirt held the dress out: over the chest the dress lies farther from the
  // body than the dress alone does (its 6 mm clearance) by about the shirt's standing off.
  int lifted = 0;
  figment::Contact c;
  for (const figment::Vec3& p : dressAtRest)
    lifted += !volumes.contact(p, 0.0, 0.05, c) && c.distance > 0.006 + thickness;
  EXPECT_GT(lifted, static_cast<int>(dressAtRest.size()) / 4);
}

TEST(LayeredGarments, ABadGroupOrSurfaceIsOneLineNamingIt) {
  initCoin();
  const std::string sheet =
      "restPoints [ 0 1 0, 0.1 1 0, 0 1 0.1 ]  coordIndex [ 0 1 2 -1 ]  maxTime 0.01\n";
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
        readString(std::string("#Inventor V2.1 ascii\nSeparator { Coordinate3 { point = DEF E ClothEngine { ") +
                   sheet + " body " + bad.body + " } . positions } }\n");
    ASSERT_TRUE(root) << bad.body << errors.all();
    ClothEngine* engine = engineNamed(root.get(), "E");
    ASSERT_NE(engine, nullptr);
    drape(*engine);
    EXPECT_NE(engine->lastError().find(bad.expected), std::string::npos) << engine->lastError();
    EXPECT_EQ(std::count(engine->lastError().begin(), engine->lastError().end(), '\n'), 0);
  }
}
