// A garment's fit measured on analytic cases: a tube round a closed cylinder (the body),
// stretched round it by a known strain or standing off it by a known distance. Stretch,
// ease, girth ease and pressure (Laplace's law for a membrane round a cylinder) must be
// those the geometry gives.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/fit/GarmentFit.h"
#include "support/FitTubes.h"

using namespace figment;

namespace {

using test::Case;
using test::kColumns;
using test::middle;

}  // namespace

TEST(GarmentFit, LargestPrincipalStrainOfAStretchedTriangle) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_NEAR(largestPrincipalStrain(a, b, c, a, b, c), 0.0, 1e-12);
  EXPECT_NEAR(largestPrincipalStrain(a, b, c, a, 1.07 * b, c), 0.07, 1e-12);         // along x
  EXPECT_NEAR(largestPrincipalStrain(a, b, c, a, b, 1.03 * c), 0.03, 1e-12);         // along y
  EXPECT_NEAR(largestPrincipalStrain(a, b, c, a, 0.9 * b, 0.95 * c), -0.05, 1e-12);  // compressed both ways
  // Rotated and moved: the same strain.
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Vec3 shift(0.3, -2, 5);
  EXPECT_NEAR(largestPrincipalStrain(a, b, c, turn * a + shift, turn * (1.07 * b) + shift, turn * c + shift), 0.07,
              1e-12);
}

// A tube cut 5 % smaller round than where it lies: every section stretched 5 % round.
TEST(GarmentFit, ATubeStretchedByFivePercentReportsFivePercent) {
  const double body = 0.15, clearance = 0.003, draped = body + clearance;
  Case c(draped / 1.05, draped, body, clearance);
  const std::vector<RegionFit> fits = measureFit(c.input, {middle(body)});
  ASSERT_EQ(fits.size(), 1u);
  EXPECT_GT(fits[0].nodes, 0);
  EXPECT_NEAR(fits[0].meanStrain, 0.05, 1e-9);
  EXPECT_NEAR(fits[0].maxStrain, 0.05, 1e-9);
  EXPECT_NEAR(fits[0].ease, 0.0, 1e-9);  // on the body, at the clearance
}

// A tube at rest length standing 2 cm off the body: ease 2 cm (less the clearance), no
// stretch, no pressure, and a girth ease of 2 pi 2 cm (less the polygons' difference).
TEST(GarmentFit, ATubeAtAKnownDistanceReportsThatEase) {
  const double body = 0.15, gap = 0.02;
  Case c(body + gap, body + gap, body, 0.003);
  const std::vector<RegionFit> fits = measureFit(c.input, {middle(body)});
  EXPECT_NEAR(fits[0].ease, gap - 0.003, 1e-9);
  EXPECT_NEAR(fits[0].meanStrain, 0.0, 1e-9);
  EXPECT_EQ(fits[0].pressure, 0.0);
  const double polygon = 2 * kColumns * std::sin(M_PI / kColumns);  // perimeter of the unit 64-gon
  EXPECT_NEAR(fits[0].girthEase, polygon * gap, 1e-6);
}

// Laplace's law: a membrane of tension T (N/m) round a cylinder of radius r presses it by
// T / r. With the tube stretched round and held lengthwise, T = E h eps / (1 - nu^2).
TEST(GarmentFit, PressureOfAStretchedTubeIsTensionOverRadius) {
  const double body = 0.15, clearance = 0.003, draped = body + clearance, strain = 0.02;
  Case c(draped / (1 + strain), draped, body, clearance);
  const Material& m = c.input.parameters.material;
  const double tension = m.youngsModulus * m.thickness * strain / (1 - m.poissonRatio * m.poissonRatio);
  const std::vector<RegionFit> fits = measureFit(c.input, {middle(body)});
  EXPECT_NEAR(fits[0].pressure, tension / draped, 0.1 * tension / draped);
  EXPECT_GT(fits[0].maxPressure, 0.0);
  // Not touching: none.
  Case off(0.2 / (1 + strain), 0.2, body, clearance);
  EXPECT_EQ(measureFit(off.input, {middle(body)})[0].pressure, 0.0);
}

TEST(GarmentFit, ARegionTheGarmentMissesIsNotCovered) {
  Case c(0.16, 0.16, 0.15, 0.003);
  FitRegion above = middle(0.15);
  above.low = 1.3, above.high = 1.4, above.girthLevel = 1.35;
  const std::vector<RegionFit> fits = measureFit(c.input, {above});
  EXPECT_FALSE(fits[0].covered());
  EXPECT_TRUE(std::isnan(fits[0].girthEase));
}

TEST(GarmentFit, PositionsThatDoNotMatchAreRefused) {
  Case c(0.16, 0.16, 0.15, 0.003);
  c.positions.pop_back();
  EXPECT_THROW(measureFit(c.input, {middle(0.15)}), std::invalid_argument);
}

// The drop tells where a garment's top edge sits in a region: 5 cm below the top of a region
// reaching over the tube's top (1.2 m). A region the tube goes on up out of has none, not
// the gap to the tube's row below its top (3 cm here, its rows being 4 cm apart), which
// changes with where the rows happen to fall on a body.
TEST(GarmentFit, DropIsWhereTheTopEdgeSitsAndNoneWhereTheGarmentGoesOnAbove) {
  Case c(0.16, 0.16, 0.15, 0.003);
  FitRegion toTheTop = middle(0.15);
  toTheTop.high = 1.25;
  EXPECT_NEAR(measureFit(c.input, {toTheTop})[0].drop, 0.05, 1e-9);
  EXPECT_EQ(measureFit(c.input, {middle(0.15)})[0].drop, 0.0);  // 0.85 to 1.15: rows at 1.12 and 1.16
}
