// What every collider has unless it says otherwise: no broad phase of its own (focusedOn
// answers null: nothing to leave out) and no motion (advanceTo changes nothing).
#include <gtest/gtest.h>

#include "sim/collision/Collider.h"
#include "sim/collision/PlaneCollider.h"

using namespace figment;

namespace {

TEST(Collider, ByDefaultHasNothingToLeaveOutAndStandsStill) {
  const PlaneCollider floor(Vec3::Zero(), Vec3::UnitY());  // overrides neither
  const Collider& body = floor;
  EXPECT_EQ(body.focusedOn(Eigen::AlignedBox3d(Vec3(-1, 1, -1), Vec3(1, 2, 1)), 0.1), nullptr);
  EXPECT_FALSE(body.moves());
  Contact before{}, after{};
  ASSERT_TRUE(body.contact(Vec3(0, -0.1, 0), 0.01, 1.0, before));
  body.advanceTo(10.0);  // s: a still collider ignores the clock
  ASSERT_TRUE(body.contact(Vec3(0, -0.1, 0), 0.01, 1.0, after));
  EXPECT_EQ(before.distance, after.distance);
  EXPECT_EQ(before.surfacePoint, after.surfacePoint);
}

}  // namespace
