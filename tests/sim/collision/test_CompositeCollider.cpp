// Several colliders as one: the deepest contact wins, ties go to the first part, and
// when nothing touches the bound is the smallest of the parts' bounds.
#include <gtest/gtest.h>

#include <limits>

#include "sim/collision/CompositeCollider.h"
#include "sim/collision/MeshCollider.h"
#include "sim/collision/MovingMeshCollider.h"
#include "sim/collision/PlaneCollider.h"
#include "support/TestMeshes.h"

namespace test_CompositeCollider {

using namespace figment;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

// A ball of radius 0.15 resting 1 cm above a floor at y = -0.16.
CompositeCollider ballOverFloor() {
  CompositeCollider body;
  body.add(std::make_shared<MeshCollider>(meshes::sphere(0.15, 48, 24)));
  body.add(std::make_shared<PlaneCollider>(Vec3(0, -0.16, 0), Vec3::UnitY()));
  return body;
}
}  // namespace

TEST(CompositeCollider, ReportsTheOnlyPartInContact) {
  const CompositeCollider body = ballOverFloor();
  Contact c;
  // Just under the floor, far from the ball.
  EXPECT_TRUE(body.contact(Vec3(1, -0.17, 0), 0.003, 0.05, c));
  EXPECT_NEAR(c.distance, -0.01, 1e-12);
  EXPECT_TRUE(c.surfacePoint.isApprox(Vec3(1, -0.16, 0)));
  EXPECT_EQ(c.normal, Vec3::UnitY());
  // Inside the top of the ball, far above the floor.
  EXPECT_TRUE(body.contact(Vec3(0, 0.14, 0), 0.003, 0.05, c));
  EXPECT_LT(c.distance, 0.0);
  EXPECT_GT(c.normal.y(), 0.99);
}

TEST(CompositeCollider, PicksTheDeepestPenetration) {
  // Two floors: a point 2 cm under the upper one and 1 cm under the lower one is pushed
  // out of the upper one, whichever order they were added in.
  auto upper = std::make_shared<PlaneCollider>(Vec3(0, 0.0, 0), Vec3::UnitY());
  auto lower = std::make_shared<PlaneCollider>(Vec3(0, -0.01, 0), Vec3::UnitY());
  const Vec3 p(0.5, -0.02, 0.5);
  for (const CompositeCollider& body : {CompositeCollider({upper, lower}), CompositeCollider({lower, upper})}) {
    Contact c;
    EXPECT_TRUE(body.contact(p, 0.003, 0.05, c));
    EXPECT_NEAR(c.distance, -0.02, 1e-15);
    EXPECT_TRUE(c.surfacePoint.isApprox(Vec3(0.5, 0.0, 0.5)));
  }
  // A point in the ball's bottom and under the floor (the floor raised into the ball).
  CompositeCollider ballInFloor;
  ballInFloor.add(std::make_shared<MeshCollider>(meshes::sphere(0.15, 48, 24)));
  ballInFloor.add(std::make_shared<PlaneCollider>(Vec3(0, -0.1, 0), Vec3::UnitY()));
  Contact c;
  ASSERT_TRUE(ballInFloor.contact(Vec3(0, -0.11, 0), 0.003, 0.05, c));  // 1 cm under the floor
  EXPECT_NEAR(c.distance, -0.04, 1e-3);                                 // but ~4 cm inside the ball: the ball wins
  EXPECT_LT(c.normal.y(), -0.99);
}

TEST(CompositeCollider, TiesGoToThePartAddedFirst) {
  // A floor and a wall meeting at a corner, the point 1 cm deep in both: the part
  // added first answers.
  auto floor = std::make_shared<PlaneCollider>(Vec3::Zero(), Vec3::UnitY());
  auto wall = std::make_shared<PlaneCollider>(Vec3::Zero(), Vec3::UnitX());
  const Vec3 p(-0.01, -0.01, 0);
  Contact c;
  ASSERT_TRUE(CompositeCollider({floor, wall}).contact(p, 0.003, 0.05, c));
  EXPECT_EQ(c.normal, Vec3::UnitY());
  ASSERT_TRUE(CompositeCollider({wall, floor}).contact(p, 0.003, 0.05, c));
  EXPECT_EQ(c.normal, Vec3::UnitX());
}

TEST(CompositeCollider, BoundIsTheSmallestBoundWhenNothingTouches) {
  const CompositeCollider body = ballOverFloor();
  Contact c;
  // Beside the ball, 4 cm above the floor: the floor's exact 0.04 is below the ball's
  // bound (its distance or the search radius).
  EXPECT_FALSE(body.contact(Vec3(0.3, -0.12, 0), 0.003, 0.5, c));
  EXPECT_NEAR(c.distance, 0.04, 1e-12);
  // High above both, a small search radius: the ball reports the radius, the floor its
  // exact 1.16; the bound is the radius.
  EXPECT_FALSE(body.contact(Vec3(0, 1.0, 0), 0.003, 0.05, c));
  EXPECT_DOUBLE_EQ(c.distance, 0.05);
  // The bound never exceeds the true distance to either part.
  const MeshCollider ball(meshes::sphere(0.15, 48, 24));
  for (const Vec3& p : {Vec3(0.2, 0.0, 0.0), Vec3(0.0, 0.3, 0.1), Vec3(-0.4, -0.1, 0.2)}) {
    Contact exact;
    ball.contact(p, 0.0, kInf, exact);
    ASSERT_FALSE(body.contact(p, 0.003, kInf, c)) << p.transpose();
    EXPECT_LE(c.distance, exact.distance + 1e-12);
    EXPECT_LE(c.distance, p.y() + 0.16 + 1e-12);
  }
}

TEST(CompositeCollider, EmptyTouchesNothingAndNullPartsAreRefused) {
  const CompositeCollider none;
  Contact c;
  EXPECT_FALSE(none.contact(Vec3::Zero(), 0.003, 0.05, c));
  EXPECT_EQ(c.distance, kInf);
  CompositeCollider body;
  EXPECT_THROW(body.add(nullptr), std::invalid_argument);
  EXPECT_THROW(CompositeCollider({std::make_shared<PlaneCollider>(Vec3::Zero(), Vec3::UnitY()), nullptr}),
               std::invalid_argument);
}

// A moving part (a posed body in a CollisionGroup) follows the drape's clock through the
// group: the group moves, and advancing it advances the part.
TEST(CompositeCollider, PassesTheClockToAMovingPart) {
  const TriangleMesh ball = meshes::sphere(0.1);
  auto moving = std::make_shared<MovingMeshCollider>(
      ball.triangles,
      [ball](double share) {
        std::vector<Vec3> v = ball.vertices;
        for (Vec3& p : v) p.x() += 0.5 * share;  // 0.5 m along +x
        return v;
      },
      1.0);
  CompositeCollider still = ballOverFloor();
  EXPECT_FALSE(still.moves());
  still.add(moving);
  EXPECT_TRUE(still.moves());
  Contact c;
  still.advanceTo(0.0);  // the moving ball at its start, round x = 0
  EXPECT_FALSE(moving->contact(Vec3(0.5, 0, 0), 0.0, 1.0, c));
  still.advanceTo(1.0);  // arrived: round x = 0.5
  EXPECT_TRUE(moving->contact(Vec3(0.5, 0, 0), 0.0, 1.0, c));
  EXPECT_TRUE(still.contact(Vec3(0.5, 0, 0), 0.0, 1.0, c));
}

}  // namespace test_CompositeCollider
