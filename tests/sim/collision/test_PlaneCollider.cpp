// The plane collider: signed distances along the normal, projections onto the plane,
// the plane's normal everywhere, exact bounds, and a zero normal refused.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sim/collision/PlaneCollider.h"

namespace test_PlaneCollider {

using namespace figment;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}

TEST(PlaneCollider, FloorGivesHeightAsSignedDistance) {
  const PlaneCollider floor(Vec3(0, -1, 0), Vec3(0, 1, 0));
  Contact c;
  EXPECT_FALSE(floor.contact(Vec3(0.3, 0.5, -2), 0.003, kInf, c));
  EXPECT_DOUBLE_EQ(c.distance, 1.5);  // false: the exact distance, a valid lower bound
  EXPECT_TRUE(c.surfacePoint.isApprox(Vec3(0.3, -1, -2)));
  EXPECT_EQ(c.normal, Vec3(0, 1, 0));

  // Below the floor: negative distance, pushed straight up onto it.
  EXPECT_TRUE(floor.contact(Vec3(2, -1.25, 7), 0.003, 0.01, c));
  EXPECT_DOUBLE_EQ(c.distance, -0.25);
  EXPECT_TRUE(c.surfacePoint.isApprox(Vec3(2, -1, 7)));
  EXPECT_EQ(c.normal, Vec3(0, 1, 0));
}

TEST(PlaneCollider, ClearanceDecidesContactAboveThePlane) {
  const PlaneCollider floor(Vec3::Zero(), Vec3::UnitY());
  Contact c;
  EXPECT_TRUE(floor.contact(Vec3(0, 0.002, 0), 0.003, kInf, c));
  EXPECT_NEAR(c.distance, 0.002, 1e-15);
  EXPECT_FALSE(floor.contact(Vec3(0, 0.004, 0), 0.003, kInf, c));
  EXPECT_NEAR(c.distance, 0.004, 1e-15);
  EXPECT_FALSE(floor.contact(Vec3::Zero(), 0.0, kInf, c));  // on the surface, no clearance
  EXPECT_EQ(c.distance, 0.0);
}

TEST(PlaneCollider, InclinedPlaneNormalisesItsNormalAndProjects) {
  // A 30 degree slope through (1, 2, 3), normal given with length 4.
  const double a = M_PI / 6;
  const Vec3 n(-std::sin(a), std::cos(a), 0.0);
  const Vec3 o(1, 2, 3);
  const PlaneCollider slope(o, 4.0 * n);
  EXPECT_NEAR(slope.normal().norm(), 1.0, 1e-15);
  EXPECT_TRUE(slope.normal().isApprox(n));
  // A point 5 cm above the slope, 20 cm along it: pushed back to the point along it.
  const Vec3 along(std::cos(a), std::sin(a), 0.0);
  const Vec3 onPlane = o + 0.2 * along + Vec3(0, 0, -0.7);
  Contact c;
  EXPECT_FALSE(slope.contact(onPlane + 0.05 * n, 0.003, kInf, c));
  EXPECT_NEAR(c.distance, 0.05, 1e-14);
  EXPECT_LT((c.surfacePoint - onPlane).norm(), 1e-14);
  EXPECT_TRUE(slope.contact(onPlane - 0.01 * n, 0.003, kInf, c));
  EXPECT_NEAR(c.distance, -0.01, 1e-14);
  EXPECT_LT((c.surfacePoint - onPlane).norm(), 1e-14);
  EXPECT_LT((c.normal - n).norm(), 1e-15);
  // The surface point plus clearance along the normal is at exactly the clearance.
  Contact pushed;
  slope.contact(c.surfacePoint + 0.003 * c.normal, 0.0, kInf, pushed);
  EXPECT_NEAR(pushed.distance, 0.003, 1e-14);
}

TEST(PlaneCollider, FindsDeepPointsWhateverTheSearchRadius) {
  // Everything behind the plane is inside, however far: the search radius only bounds
  // where a mesh looks, an infinite plane is always found.
  const PlaneCollider floor(Vec3::Zero(), Vec3::UnitY());
  Contact c;
  EXPECT_TRUE(floor.contact(Vec3(0, -10, 0), 0.003, 0.01, c));
  EXPECT_DOUBLE_EQ(c.distance, -10.0);
  EXPECT_FALSE(floor.contact(Vec3(0, 10, 0), 0.003, 0.01, c));
  EXPECT_DOUBLE_EQ(c.distance, 10.0);
}

TEST(PlaneCollider, RejectsAZeroNormalNamingIt) {
  try {
    PlaneCollider plane(Vec3::Zero(), Vec3::Zero());
    FAIL() << "no error";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("normal"), std::string::npos) << error.what();
  }
  EXPECT_THROW(PlaneCollider(Vec3::Zero(), Vec3(kInf, 0, 0)), std::invalid_argument);
  EXPECT_THROW(PlaneCollider(Vec3(std::nan(""), 0, 0), Vec3::UnitY()), std::invalid_argument);
}

}  // namespace test_PlaneCollider
