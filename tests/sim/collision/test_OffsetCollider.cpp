// A surface moved out along its normal (sim/collision/OffsetCollider.h): an inner
// garment's surface with its thickness on it.
#include <gtest/gtest.h>

#include <limits>
#include <memory>

#include "sim/collision/MeshCollider.h"
#include "sim/collision/MovingMeshCollider.h"
#include "sim/collision/OffsetCollider.h"
#include "support/TestMeshes.h"

using namespace figment;

TEST(OffsetCollider, MovesTheSurfaceOutByItsOffset) {
  const double radius = 0.1, offset = 0.004;
  auto ball = std::make_shared<MeshCollider>(meshes::sphere(radius, 96, 48));
  const OffsetCollider thick(ball, offset);
  const double inf = std::numeric_limits<double>::infinity();
  const Vec3 p(0.0, 0.0, radius + 0.01);  // 1 cm off the ball, 6 mm off its thick surface
  Contact c;
  EXPECT_FALSE(thick.contact(p, 0.003, inf, c));
  EXPECT_NEAR(c.distance, 0.006, 1e-4);
  ASSERT_TRUE(thick.contact(p, 0.007, inf, c));
  EXPECT_NEAR(c.distance, 0.006, 1e-4);
  EXPECT_NEAR(c.surfacePoint.norm(), radius + offset, 1e-4);
  EXPECT_NEAR(c.normal.z(), 1.0, 1e-6);
  // Inside the thickness, outside the ball: inside the thick surface.
  ASSERT_TRUE(thick.contact(Vec3(0.0, 0.0, radius + 0.001), 0.0, inf, c));
  EXPECT_NEAR(c.distance, -0.003, 1e-4);
}

TEST(OffsetCollider, RefusesNoColliderAndANegativeOffset) {
  EXPECT_THROW(OffsetCollider(nullptr, 0.001), std::invalid_argument);
  auto ball = std::make_shared<MeshCollider>(meshes::sphere(0.1));
  EXPECT_THROW(OffsetCollider(ball, -0.001), std::invalid_argument);
  EXPECT_THROW(OffsetCollider(ball, std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
}

// A surface that moves moves its offset too: the clock passes through to it.
TEST(OffsetCollider, PassesTheClockToAMovingSurface) {
  const TriangleMesh ball = meshes::sphere(0.1);
  auto moving = std::make_shared<MovingMeshCollider>(
      ball.triangles,
      [ball](double share) {
        std::vector<Vec3> v = ball.vertices;
        for (Vec3& p : v) p.x() += 0.5 * share;
        return v;
      },
      1.0);
  const OffsetCollider offset(moving, 0.01);
  EXPECT_TRUE(offset.moves());
  EXPECT_FALSE(OffsetCollider(std::make_shared<MeshCollider>(ball), 0.01).moves());
  Contact c;
  offset.advanceTo(0.0);
  EXPECT_FALSE(offset.contact(Vec3(0.5, 0, 0), 0.0, 1.0, c));
  offset.advanceTo(1.0);
  EXPECT_TRUE(offset.contact(Vec3(0.5, 0, 0), 0.0, 1.0, c));
}
