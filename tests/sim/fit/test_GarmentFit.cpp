// A garment's fit measured on analytic cases: a tube round a closed cylinder (the body),
// stretched round it by a known strain or standing off it by a known distance. Stretch,
// ease, girth ease and pressure (Laplace's law for a membrane round a cylinder) must be
// those the geometry gives. A rest shape apart from the rest mesh (a sewn garment's flat
// panels) is what stretch is measured against.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/cloth/RestShape.h"
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

// A sewn garment: the mesh is where its panels were placed, its rest shape each section's
// own corners. The same tube lying as cut, with sections whose corners at rest are 5 %
// smaller: 5 % stretch, as the tube cut 5 % smaller round reports, where the mesh alone
// reports none.
TEST(GarmentFit, ARestShapeApartFromTheMeshIsWhatStretchIsMeasuredAgainst) {
  const double body = 0.15, clearance = 0.003, draped = body + clearance;
  Case c(draped, draped, body, clearance);
  std::vector<std::array<Vec3, 3>> corners;
  for (const Triangle& t : c.rest.triangles)
    corners.push_back({c.rest.vertices[t[0]] / 1.05, c.rest.vertices[t[1]] / 1.05, c.rest.vertices[t[2]] / 1.05});
  const RestShape smaller = RestShape::flatPieces(c.rest.triangles, corners, c.rest.vertices.size());
  EXPECT_NEAR(measureFit(c.input, {middle(body)})[0].meanStrain, 0.0, 1e-9);  // the control
  c.input.restShape = &smaller;
  const std::vector<RegionFit> fits = measureFit(c.input, {middle(body)});
  EXPECT_NEAR(fits[0].meanStrain, 0.05, 1e-9);
  EXPECT_GT(fits[0].pressure, 0.0);  // the forces, too, are the rest shape's
  // A rest shape of other sections is refused.
  const RestShape other = RestShape::flatPieces({c.rest.triangles[0]}, {corners[0]}, c.rest.vertices.size());
  c.input.restShape = &other;
  EXPECT_THROW(measureFit(c.input, {middle(body)}), std::invalid_argument);
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

// On a posed body the regions are the standing body's: a tube 2 cm off a cylinder turned
// 90 degrees (an arm raised to level) measures as it did standing, node for node, where
// told by where it lies it is in no region at all (the control).
TEST(GarmentFit, AGarmentOnATurnedLimbMeasuresAsStanding) {
  const double body = 0.15, gap = 0.02;
  Case standing(body + gap, body + gap, body, 0.003);
  const RegionFit upright = measureFit(standing.input, {middle(body)})[0];
  const auto turn = [](const Vec3& p) -> Vec3 {
    return Vec3(0, 0.5, 0) + Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()) * (p - Vec3(0, 0.5, 0));
  };
  TriangleMesh posedBody = test::cylinder(body);
  for (Vec3& p : posedBody.vertices) p = turn(p);
  const PosedSkin skin(test::cylinder(body), posedBody);
  const MeshCollider posedCollider(posedBody);
  std::vector<Vec3> posed = standing.positions;
  for (Vec3& p : posed) p = turn(p);
  FitInput input = standing.input;
  input.positions = &posed;
  input.body = &posedCollider;
  EXPECT_FALSE(measureFit(input, {middle(body)})[0].covered());  // told where it lies
  input.pose = &skin;
  const RegionFit raised = measureFit(input, {middle(body)})[0];
  EXPECT_EQ(raised.nodes, upright.nodes);
  EXPECT_NEAR(raised.ease, upright.ease, 1e-9);
  EXPECT_NEAR(raised.meanStrain, upright.meanStrain, 1e-9);
  EXPECT_NEAR(raised.girthEase, upright.girthEase, 1e-9);
  EXPECT_NEAR(raised.drop, upright.drop, 1e-9);
  EXPECT_EQ(raised.unmeasured, "");
}

// Cloth pinched between two limbs the pose brought together (cylinders 30 cm apart at
// rest, 4 cm posed) parts when carried back: each node goes with its own limb, and the
// edges across the gap grow from 2 cm to 28. Its girth is then told as unmeasured, with
// why, not as a number; standing, the same cloth is measured.
TEST(GarmentFit, ClothPinchedBetweenLimbsThePoseJoinedIsUnmeasured) {
  const auto pair = [](double centre) {
    TriangleMesh both;
    for (const double x : {-centre, centre}) {
      TriangleMesh one = test::cylinder(0.15);
      const int base = static_cast<int>(both.vertices.size());
      for (const Vec3& p : one.vertices) both.vertices.push_back(p + Vec3(x, 0, 0));
      for (const Triangle& t : one.triangles) both.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    }
    return both;
  };
  const PosedSkin skin(pair(0.3), pair(0.17));
  const MeshCollider posedCollider(skin.posed());
  TriangleMesh sheet;  // two columns, at x = -1 and +1 cm, y from 0.8 to 1.2 m
  for (int row = 0; row <= 10; ++row)
    for (const double x : {-0.01, 0.01}) sheet.vertices.emplace_back(x, 0.8 + 0.04 * row, 0);
  for (int row = 0; row < 10; ++row) {
    const int a = 2 * row;
    sheet.triangles.push_back({a, a + 1, a + 2});
    sheet.triangles.push_back({a + 1, a + 3, a + 2});
  }
  FitInput input;
  input.rest = &sheet;
  input.positions = &sheet.vertices;
  input.body = &posedCollider;
  input.parameters.clearance = 0.003;
  input.parameters.gravity = Vec3::Zero();
  const FitRegion region = middle(0.15);
  EXPECT_EQ(measureFit(input, {region})[0].unmeasured, "");  // standing
  input.pose = &skin;
  const RegionFit pinched = measureFit(input, {region})[0];
  ASSERT_TRUE(pinched.covered());
  EXPECT_NE(pinched.unmeasured.find("the pose folds the skin under it"), std::string::npos) << pinched.unmeasured;
  EXPECT_TRUE(std::isnan(pinched.girthEase));
  EXPECT_NEAR(pinched.ease, 0.01 - 0.003, 1e-9);  // measured on the posed skin: 1 cm off it
}
