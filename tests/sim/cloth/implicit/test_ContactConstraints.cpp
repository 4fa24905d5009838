// ContactConstraints: the body's contacts in a backward Euler step. A node held and
// pressing that ends its step a little above the clearance (sliding along its tangent
// plane over a curved body drifts it off by d^2 / 2R) is put back on the clearance,
// so it stays held instead of falling back in and being pushed out every other step;
// a node lifting off, or one farther off, is left where it is. A node pushed out of one
// side of a crease into the other is pushed out of that one too.
#include <gtest/gtest.h>

#include "sim/cloth/implicit/ContactConstraints.h"
#include "sim/collision/CompositeCollider.h"
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

// A crease: the body is everything below y = 0 and everything on the far side of a plane
// through the origin whose outward normal is `side` (x = 0's, +x, unless said: the body
// also left of x = 0, the space outside it the quarter x, y > 0, as an armpit's between
// arm and torso). A free node the solve moved from `xStart` to `x`, at speed `v` (-8 cm/s
// along x, into the upright side): where finish() leaves it (its velocity in `v`).
Vec3 finishInCrease(bool leaveCreases, const Vec3& xStart, const Vec3& x, Vec3& v, const Vec3& side = Vec3::UnitX()) {
  ClothParameters p;
  p.integrator = Integrator::Implicit;
  p.timeStep = kDt;
  p.clearance = kClearance;
  p.implicitSolver.leaveCreases = leaveCreases;
  auto body = std::make_shared<CompositeCollider>(
      std::vector<std::shared_ptr<const Collider>>{std::make_shared<PlaneCollider>(Vec3::Zero(), side),
                                                   std::make_shared<PlaneCollider>(Vec3::Zero(), Vec3::UnitY())});
  ContactConstraints contacts(body, p, 1);
  NodeFilter filter;
  filter.reset(1);  // free: the solve moved it into the body
  std::vector<Vec3> xs{x}, vs{Vec3(-0.08, 0.0, 0.0)};
  contacts.finish(filter, {xStart}, {Vec3::Zero()}, kDt, false, xs, vs);
  v = vs[0];
  return xs[0];
}

// A node resting 0.5 mm inside the floor, which the solve left 1 mm inside the upright side
// too, is pushed out of the upright side (its deepest contact) to x = clearance, still
// inside the floor: before, it ended there (the women's 7XL T-shirt rested with 4 nodes up
// to 0.9 mm inside the arm, where it meets the torso).
TEST(ContactConstraintsCrease, ANodePushedOutOfOneSideIntoTheOtherIsPushedOutOfThatToo) {
  Vec3 v;
  const Vec3 x = finishInCrease(true, Vec3(0.003, -0.0005, 0.0), Vec3(-0.001, -0.0005, 0.0), v);
  EXPECT_NEAR(x.x(), kClearance, 1e-12);  // out of the upright side, at its clearance
  EXPECT_NEAR(x.y(), kClearance, 1e-12);  // and out of the floor, at its clearance
  EXPECT_GE(v.x(), 0.0);                  // moving into neither side
  EXPECT_GE(v.y(), 0.0);
}

// A crease of 160 degrees, the floor and a side leaning 20 degrees over it (an arm pressed
// to the torso): pushed along each side's normal in turn, a node the solve left 0.7 mm
// inside the leaning side ended 0.9 mm inside the floor after four pushes (the women's 7XL
// T-shirt, draped on its chart body as the service makes it, rested with 2 nodes 1 mm
// inside, 1.23 m up at the armpit). It leaves along the crease's bisector, outside both.
TEST(ContactConstraintsCrease, ANodeInANarrowCreaseLeavesItAlongItsBisector) {
  const double tilt = 20.0 * M_PI / 180.0;
  const Vec3 side(std::sin(tilt), -std::cos(tilt), 0.0);  // outside: 0 < y < x tan 20 degrees
  const Vec3 x0(0.002, 0.0015, 0.0);
  ASSERT_LT(side.dot(x0), -5e-4);  // the solve left it inside the leaning side
  Vec3 v;
  const Vec3 x = finishInCrease(true, Vec3(0.01, 0.001, 0.0), x0, v, side);
  EXPECT_GE(x.y(), 0.0);                         // outside the floor
  EXPECT_GE(side.dot(x), 0.0);                   // and the leaning side
  EXPECT_LE((x - x0).norm(), 5.0 * kClearance);  // no farther than a few clearances
  EXPECT_GE(v.dot(side), -1e-12);                // moving into neither side
  EXPECT_GE(v.y(), -1e-12);
}

// A node only within the other side's clearance is left there: the push is for a node
// inside the body (pushing every node out of both clearances in a crease tore the women's
// fitted shirt in 3XL and 4XL, whose seams close across the armpits).
TEST(ContactConstraintsCrease, ANodeLeftWithinTheOtherSidesClearanceStaysThere) {
  Vec3 v;
  const Vec3 x = finishInCrease(true, Vec3(0.003, 0.003, 0.0), Vec3(-0.001, 0.003, 0.0), v);
  EXPECT_NEAR(x.x(), kClearance, 1e-12);
  EXPECT_NEAR(x.y(), 0.003, 1e-12);
}

// Off (the default, ImplicitSolverParameters::leaveCreases): the node pushed out of the
// upright side is left inside the floor, as a shirt's side between arm and torso is left.
TEST(ContactConstraintsCrease, OffTheNodeIsPushedOutOfItsDeepestSideAlone) {
  Vec3 v;
  const Vec3 x = finishInCrease(false, Vec3(0.003, -0.0005, 0.0), Vec3(-0.001, -0.0005, 0.0), v);
  EXPECT_NEAR(x.x(), kClearance, 1e-12);
  EXPECT_NEAR(x.y(), -0.0005, 1e-12);
}

}  // namespace test_ContactConstraints
