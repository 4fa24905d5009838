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
// T / r. The cloth is St. Venant-Kirchhoff in the Green strain (sim/cloth/PlaneStressLaw.h):
// a tube stretched round by lambda = 1 + eps and held lengthwise has a hoop Green strain of
// (lambda^2 - 1) / 2, a hoop stress S = E / (1 - nu^2) of it, and a tension per length of
// the (unstretched) axis T = h lambda S: T = E h lambda (lambda^2 - 1) / 2 (1 - nu^2), which
// is the linear E h eps / (1 - nu^2) times 1 + 3 eps / 2 + eps^2 / 2 (3 % more at 2 %).
//
// The budget: the tube is a regular 64-gon, every section a right triangle stretched along
// one leg, so each section's strain is the tube's exactly and its force is that of the
// tension on its sides. A node's two hoop sides pull it inward by 2 T H sin(pi / n) (H the
// rows' spacing) and its share of the draped area is 2 r sin(pi / n) H: the polygon's sine
// cancels, and T / r holds node by node with r the draped polygon's radius, with no
// discretisation error. A radial stretch keeps every dihedral angle, so bending adds
// nothing; the rows in the region are interior, their axial tensions balanced. What is left
// is rounding: 1e-9 of the pressure. The region's pressure is the same T / r, its mean. So a
// pressure a factor 1 + eps off (the tension over the rest radius, or over the rest area)
// fails, as does one on the body's radius (2 % off) or the linear tension (3 % off).
TEST(GarmentFit, PressureOfAStretchedTubeIsTensionOverRadius) {
  constexpr double kRounding = 1e-9;  // of the pressure (see above)
  const double clearance = 0.003, strain = 0.02, lambda = 1 + strain;
  // Two bodies: the pressure goes as one over the radius, at the same tension.
  for (const double body : {0.15, 0.10}) {
    SCOPED_TRACE(body);
    const double draped = body + clearance;
    Case c(draped / lambda, draped, body, clearance);
    const Material& m = c.input.parameters.material;
    const double tension =
        m.youngsModulus * m.thickness * lambda * (lambda * lambda - 1) / (2 * (1 - m.poissonRatio * m.poissonRatio));
    const RegionFit fit = measureFit(c.input, {middle(body)})[0];
    EXPECT_NEAR(fit.pressure, tension / draped, kRounding * tension / draped);
    // Every node in the region presses alike: the largest is the mean.
    EXPECT_NEAR(fit.maxPressure, tension / draped, kRounding * tension / draped);
  }
  // Not touching: none.
  Case off(0.2 / lambda, 0.2, 0.15, clearance);
  EXPECT_EQ(measureFit(off.input, {middle(0.15)})[0].pressure, 0.0);
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
