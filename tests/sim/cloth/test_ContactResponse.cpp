// The contact response on one node against a floor (normal +y, surface y = 0) whose answer
// is known: where the node ends, the velocity it keeps, and Coulomb's static and sliding cases.
#include <gtest/gtest.h>

#include "sim/cloth/ContactResponse.h"
#include "sim/collision/PlaneCollider.h"

namespace test_ContactResponse {

using namespace figment;

namespace {

constexpr double kClearance = 0.01, kStep = 0.01;  // m, s

Contact floorBelow(const Vec3& x) {
  return {Vec3(x.x(), 0, x.z()), Vec3::UnitY(), x.y()};
}

TEST(ContactResponse, NodeFallingIntoTheFloorEndsOnTheClearanceWithNoSpeedIntoIt) {
  const Vec3 before(0, 0.02, 0);
  Vec3 x(0, -0.01, 0), v(0, -3, 0);
  respondToContact(floorBelow(x), kClearance, 0.0, kStep, before, x, v);
  EXPECT_NEAR(x.y(), kClearance, 1e-12);
  // The push-out is not a launch: the node had no speed away from the floor, so it keeps none.
  EXPECT_NEAR(v.y(), 0.0, 1e-12);
}

TEST(ContactResponse, FrictionHoldsASlowSlideAndSlowsAFastOne) {
  // Removed normal speed 1 m/s; friction 0.5: a tangential speed up to 0.5 m/s is held.
  const Vec3 before(0, 0.01, 0);
  Vec3 x(0.003, -0.0, 0), v(0.3, -1, 0);
  respondToContact(floorBelow(x), kClearance, 0.5, kStep, before, x, v);
  EXPECT_NEAR(v.norm(), 0.0, 1e-12);      // static: stopped
  EXPECT_NEAR(x.x(), before.x(), 1e-12);  // and kept its place from the step's start
  EXPECT_NEAR(x.y(), kClearance, 1e-12);
  Vec3 y(0.02, 0.0, 0), w(2.0, -1, 0);
  respondToContact(floorBelow(y), kClearance, 0.5, kStep, before, y, w);
  EXPECT_NEAR(w.x(), 2.0 - 0.5 * 1.0, 1e-12);  // sliding: slowed by mu times 1 m/s
  EXPECT_NEAR(y.x(), 0.02, 1e-12);             // on the surface where it is
  EXPECT_NEAR(y.y(), kClearance, 1e-12);
}

TEST(ContactResponse, RespondIfTouchingSkipsTheQueryWhileTheBoundHolds) {
  const PlaneCollider floor(Vec3::Zero(), Vec3::UnitY());
  Vec3 before(0, 0.5, 0), x(0, 0.49, 0), v(0, -1, 0);
  double bound = 0.5;  // m: the node was at least 0.5 m away
  respondIfTouching(floor, kClearance, 0.0, kStep, false, 0.0, before, x, v, bound);
  EXPECT_NEAR(bound, 0.49, 1e-12);  // lowered by the 1 cm moved; no query, no change
  EXPECT_EQ(v, Vec3(0, -1, 0));
  // Below the floor with the bound used up: answered and pushed out.
  before = Vec3(0, 0.005, 0);
  x = Vec3(0, -0.005, 0);
  bound = 0.0;
  respondIfTouching(floor, kClearance, 0.0, kStep, false, 0.0, before, x, v, bound);
  EXPECT_NEAR(x.y(), kClearance, 1e-12);
  EXPECT_DOUBLE_EQ(bound, kClearance);
}

}  // namespace

}  // namespace test_ContactResponse
