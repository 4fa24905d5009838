// The flared skirt of scenes/skirt.iv under the implicit integrator at 1/20 s: it slides
// onto the hips and comes to rest on the default collision volumes (no node left
// chattering), with no node inside any volume and no edge torn.
#include "nodes/body/CollisionBody.h"
#include "sim/collision/Collider.h"
#include "support/ShippedGarmentScene.h"

#include <Inventor/fields/SoMFVec3f.h>

#include <gtest/gtest.h>

using namespace figment::test;

TEST(SkirtImplicit, ComesToRestOnTheVolumesWithNoNodeInside) {
  const ShippedGarmentScene scene("skirt.iv");
  ASSERT_NE(scene.engine(), nullptr);
  ClothEngine& engine = *scene.engine();
  engine.integrator = ClothEngine::IMPLICIT;
  engine.timeStep = 0.05;
  SoMFVec3f positions;
  positions.connectFrom(&engine.positions);
  positions.evaluate();
  ASSERT_EQ(engine.lastError(), "");
  EXPECT_TRUE(engine.lastRun().atRest) << "t = " << engine.lastRun().simulatedSeconds << " s";
  const figment::CollisionBody* body = figment::asCollisionBody(engine.body.getValue());
  ASSERT_NE(body, nullptr);
  const std::shared_ptr<const figment::Collider> volumes = body->bodyCollider();
  int inside = 0;
  double lowest = 10.0;
  for (int i = 0; i < positions.getNum(); ++i) {
    const SbVec3f& p = positions[i];
    figment::Contact contact;
    if (volumes->contact(figment::Vec3(p[0], p[1], p[2]), 0.0, 0.05, contact) && contact.distance < 0.0) ++inside;
    lowest = std::min(lowest, static_cast<double>(p[1]));
  }
  EXPECT_EQ(inside, 0);
  EXPECT_GT(lowest, 0.3);  // on the hips, not fallen to the floor
}
