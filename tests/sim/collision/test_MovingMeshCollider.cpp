// A surface moving during a drape: keyframes at most maxStep apart, the drape's clock
// moving it, lower bounds that allow for the motion still to come, and the final surface's
// answers once it has arrived.
#include <gtest/gtest.h>

#include "sim/collision/MovingMeshCollider.h"
#include "support/TestMeshes.h"

using namespace figment;

namespace {

// A 10 cm sphere moving 0.5 m along +x.
MovingMeshCollider movingSphere(double duration) {
  const TriangleMesh ball = meshes::sphere(0.1);
  return MovingMeshCollider(
      ball.triangles,
      [ball](double share) {
        std::vector<Vec3> v = ball.vertices;
        for (Vec3& p : v) p.x() += 0.5 * share;
        return v;
      },
      duration);
}

}  // namespace

TEST(MovingMeshCollider, StandsAtItsLastShapeUntilTheClockMovesIt) {
  const MovingMeshCollider moving = movingSphere(2.0);
  EXPECT_NEAR(moving.travel(), 0.5, 1e-9);
  EXPECT_NEAR(moving.keyframes(), 50, 1);  // 1 cm apart
  Contact c;
  EXPECT_TRUE(moving.contact(Vec3(0.5, 0, 0), 0.0, 1.0, c));  // the centre of the final sphere
  moving.advanceTo(0.0);
  EXPECT_FALSE(moving.contact(Vec3(0.5, 0, 0), 0.0, 1.0, c));
  // still to move 0.5 m: the bound says the point may be reached
  EXPECT_EQ(c.distance, 0.0);
  EXPECT_TRUE(moving.contact(Vec3(0, 0, 0), 0.0, 1.0, c));
  moving.advanceTo(1.0);                                        // half way: centre at x = 0.25
  EXPECT_TRUE(moving.contact(Vec3(0.3, 0, 0), 0.0, 0.001, c));  // found beyond the caller's radius
  EXPECT_NEAR(c.distance, -0.05, 0.01);                         // (a polygonal sphere, a keyframe at or before)
  EXPECT_GT(c.normal.x(), 0.99);                                // pushed out ahead of the motion, the side it came from
  moving.advanceTo(5.0);                                        // arrived: the final sphere's own answers
  EXPECT_FALSE(moving.contact(Vec3(0.5, 0.3, 0), 0.0, 1.0, c));
  EXPECT_NEAR(c.distance, 0.2, 0.002);
}

TEST(MovingMeshCollider, ADurationOfZeroTakesAsLongAsTheFarthestPointNeedsAtItsSpeed) {
  EXPECT_NEAR(movingSphere(0.0).duration(), 0.5 / MovingMeshCollider::kSpeed, 1e-9);
  EXPECT_THROW(movingSphere(-1.0), std::invalid_argument);
}
