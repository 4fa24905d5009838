// ContactConstraints: the body's contacts in a backward Euler step. A node held and
// pressing that ends its step a little above the clearance (sliding along its tangent
// plane over a curved body drifts it off by d^2 / 2R) is put back on the clearance,
// so it stays held instead of falling back in and being pushed out every other step;
// a node lifting off, or one farther off, is left where it is.
#include <gtest/gtest.h>

#include "sim/cloth/implicit/ContactConstraints.h"
#include "sim/collision/PlaneCollider.h"

namespace test_ContactConstraints {

using namespace figment;

namespace {
constexpr double kClearance = 0.006;  // m
constexpr double kDrift = 6e-5;       // m: a strap node of the dress slid this far off
constexpr double kDt = 0.05;          // s

class ContactConstraintsTest : public ::testing::Test {
 protected:
  ContactConstraintsTest() : contacts_(std::make_shared<PlaneCollider>(Vec3::Zero(), Vec3::UnitY()), parameters(), 1) {
    filter_.reset(1);
  }

  static ClothParameters parameters() {
    ClothParameters p;
    p.integrator = Integrator::Implicit;
    p.timeStep = kDt;
    p.clearance = kClearance;
    return p;
  }
  // A step of the node from the clearance, at rest, the body pushing back with
  // `normalImpulse` N s, that the solve ends at height `yEnd` moving `vEnd`; returns
  // where finish() leaves it (its velocity in `v`).
  Vec3 step(double normalImpulse, double yEnd, Vec3& v) {
    const std::vector<Vec3> xStart{Vec3(0, kClearance, 0)}, vStart{Vec3::Zero()};
    contacts_.constrain(xStart, vStart, kDt, false, filter_);
    EXPECT_NE(filter_.kind[0], NodeFilter::Free);  // held at the clearance
    contacts_.update({Vec3(0, normalImpulse, 0)}, vStart, {v}, {0.001}, filter_);
    std::vector<Vec3> x{Vec3(0.0008, yEnd, 0)}, vEnd{v};
    contacts_.finish(filter_, xStart, vStart, kDt, false, x, vEnd);
    v = vEnd[0];
    return x[0];
  }

  ContactConstraints contacts_;
  NodeFilter filter_;
};
}  // namespace

TEST_F(ContactConstraintsTest, AHeldNodeEndingJustAboveTheClearanceIsPutBackOnIt) {
  Vec3 v(0.016, 0.0012, 0.0);  // sliding, and drifting off as it went
  const Vec3 x = step(+1e-3, kClearance + kDrift, v);
  EXPECT_NEAR(x.y(), kClearance, 1e-12);
  EXPECT_DOUBLE_EQ(x.x(), 0.0008);  // along the surface it went where it slid
  EXPECT_LE(v.y(), 0.0);            // and moves no farther away
  EXPECT_DOUBLE_EQ(v.x(), 0.016);
}

TEST_F(ContactConstraintsTest, ANodeLiftingOffOrFartherOffIsLeftWhereItIs) {
  Vec3 v(0.0, 0.0012, 0.0);
  EXPECT_NEAR(step(-1e-3, kClearance + kDrift, v).y(), kClearance + kDrift, 1e-12);  // pulled: lifting off
  v = Vec3(0.0, 0.02, 0.0);
  EXPECT_NEAR(step(+1e-3, kClearance + 1e-3, v).y(), kClearance + 1e-3, 1e-12);  // a millimetre off is off
}

}  // namespace test_ContactConstraints
