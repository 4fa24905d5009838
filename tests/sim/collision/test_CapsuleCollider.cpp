// The default capsule (radius 1/2 about the y axis at its middle) as a collider: a point
// inside is pushed to the side it is nearest; a far one is answered from the bounding
// sphere with a distance that is a lower bound.
#include <gtest/gtest.h>

#include "sim/collision/CapsuleCollider.h"

namespace test_CapsuleCollider {

using namespace figment;

namespace {

constexpr double kClearance = 0.01;  // m

TEST(CapsuleCollider, PointInsideAtTheMiddleGoesOutSideways) {
  const CapsuleCollider capsule{CapsuleParameters{}};
  Contact out{};
  ASSERT_TRUE(capsule.contact(Vec3(0.4, 0, 0), kClearance, 1.0, out));
  EXPECT_NEAR(out.distance, -0.1, 1e-6);
  EXPECT_TRUE(out.surfacePoint.isApprox(Vec3(0.5, 0, 0), 1e-6)) << out.surfacePoint.transpose();
  EXPECT_TRUE(out.normal.isApprox(Vec3::UnitX(), 1e-6)) << out.normal.transpose();
}

TEST(CapsuleCollider, PointWithinTheClearanceTouches) {
  const CapsuleCollider capsule{CapsuleParameters{}};
  Contact out{};
  EXPECT_TRUE(capsule.contact(Vec3(0, 0, 0.505), kClearance, 1.0, out));
  EXPECT_NEAR(out.distance, 0.005, 1e-4);  // m: the fast path's accuracy
  EXPECT_FALSE(capsule.contact(Vec3(0, 0, 0.52), kClearance, 1.0, out));
  EXPECT_NEAR(out.distance, 0.02, 1e-4);
}

TEST(CapsuleCollider, FarPointIsAnsweredWithALowerBoundOfItsDistance) {
  const CapsuleCollider capsule{CapsuleParameters{}};
  Contact out{};
  EXPECT_FALSE(capsule.contact(Vec3(2, 0, 0), kClearance, 1.0, out));
  // The true distance is 1.5 m; the bounding sphere's (radius at most sqrt(3)/2) is less.
  EXPECT_GT(out.distance, 2.0 - std::sqrt(3.0) / 2 - 1e-12);
  EXPECT_LE(out.distance, 1.5);
}

}  // namespace

}  // namespace test_CapsuleCollider
