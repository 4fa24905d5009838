// The boundary's turning split into its geodesic part (within the cloth) and its normal part
// (with the cloth) on analytic shapes: a flat strip rolled round a cylinder keeps a
// geodesic turning of 0 along its long edges while its 3D turning grows as the roll
// tightens; a regular n-gon turns 360/n degrees towards the cloth at each corner, a hole
// 360/n away from it, a cone's rim by its triangles' apex angle; a saw-tooth cut alternates
// in sign; over a flat disc's loop the geodesic turning sums to 360 degrees (Gauss-Bonnet).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sim/core/BoundaryLoops.h"
#include "sim/core/BoundaryTurning.h"
#include "support/TestMeshes.h"

using namespace figment;

namespace {

double geodesicSum(const std::vector<BoundaryTurning::Turn>& loop) {
  double sum = 0.0;
  for (const BoundaryTurning::Turn& turn : loop) sum += turn.geodesic;
  return sum;
}

// A strip along x, flat in the plane normal to `normal` through the origin, rolled round
// the axis through `radius` * `normal` perpendicular to x and `normal`: a length x along
// the strip becomes an arc of that length. A quad of meshes::grid stays a flat rectangle
// (its two sides across the strip are parallel to the axis), so its triangles keep their
// angles.
std::vector<Vec3> rolled(const std::vector<Vec3>& flat, double radius, const Vec3& normal) {
  std::vector<Vec3> out;
  for (const Vec3& x : flat) {
    const double a = x.x() / radius;
    out.push_back(x - x.x() * Vec3::UnitX() + radius * std::sin(a) * Vec3::UnitX() +
                  radius * (1.0 - std::cos(a)) * normal);
  }
  return out;
}

// A flat annulus in the plane y = 0: an inner regular n-gon of radius r (the hole) and an
// outer one of radius 2 r, joined by n quads. Inner vertex k is k, outer n + k.
TriangleMesh annulus(int n, double r) {
  TriangleMesh mesh;
  for (double radius : {r, 2.0 * r})
    for (int k = 0; k < n; ++k) {
      const double a = 2.0 * M_PI * k / n;
      mesh.vertices.emplace_back(radius * std::cos(a), 0.0, -radius * std::sin(a));
    }
  for (int k = 0; k < n; ++k) {
    const int a = k, b = (k + 1) % n;
    mesh.triangles.push_back({a, n + a, n + b});
    mesh.triangles.push_back({a, n + b, b});
  }
  return mesh;
}

}  // namespace

TEST(BoundaryTurning, ARolledStripTurnsIn3DButNotWithinTheCloth) {
  constexpr int kColumns = 24;
  constexpr double kLength = 0.6, kWidth = 0.1;
  const TriangleMesh strip = meshes::grid(kColumns, 4, kLength, kWidth);
  const BoundaryTurning turning(strip.triangles);
  ASSERT_EQ(turning.loops().size(), 1u);
  double previousTotal = -1.0;
  for (double radius : {10.0, 0.4, 0.2, 0.12}) {  // 2 pi 0.12 > 0.6: the roll does not close
    const std::vector<Vec3> x = rolled(strip.vertices, radius, Vec3::UnitZ());
    const std::vector<BoundaryTurning::Turn> loop = turning.turns(x).front();
    for (const BoundaryTurning::Turn& turn : loop) {
      const double along = strip.vertices[turn.vertex].x(), across = strip.vertices[turn.vertex].y();
      const bool end = along < 1e-9 || along > kLength - 1e-9,
                 side = std::abs(across) < 1e-9 || across < -kWidth + 1e-9;
      if (end && side) {  // a corner
        EXPECT_NEAR(turn.geodesic, 90.0, 1e-9);
        EXPECT_NEAR(turn.total, 90.0, 1e-9);
      } else if (side) {  // along a long edge: round the cylinder
        EXPECT_NEAR(turn.geodesic, 0.0, 1e-9) << radius;
        EXPECT_NEAR(turn.total, kLength / kColumns / radius * 180.0 / M_PI, 1e-9) << radius;
        EXPECT_NEAR(turn.normal, turn.total, 1e-6) << radius;
      } else {  // an end, parallel to the axis
        EXPECT_NEAR(turn.geodesic, 0.0, 1e-9);
        EXPECT_NEAR(turn.total, 0.0, 1e-6);
      }
    }
    EXPECT_NEAR(geodesicSum(loop), 360.0, 1e-9) << "a flat disc";
    const BoundaryTurning::Summary summary = turning.summary(x);
    EXPECT_NEAR(summary.geodesic, 0.0, 1e-9);
    EXPECT_GT(summary.total, previousTotal) << radius;
    EXPECT_EQ(summary.zigZagShare, 0.0);
    previousTotal = summary.total;
  }
}

TEST(BoundaryTurning, ARegularPolygonHoleTurnsAwayFromTheCloth) {
  for (int n : {5, 12, 40}) {
    const TriangleMesh ring = annulus(n, 0.1);
    const BoundaryTurning turning(ring.triangles);
    const std::vector<std::vector<BoundaryTurning::Turn>> loops = turning.turns(ring.vertices);
    ASSERT_EQ(loops.size(), 2u);
    for (const std::vector<BoundaryTurning::Turn>& loop : loops) {
      ASSERT_EQ(static_cast<int>(loop.size()), n);
      const bool hole = loop.front().vertex < n;
      for (const BoundaryTurning::Turn& turn : loop) {
        EXPECT_EQ(turn.vertex < n, hole);
        EXPECT_NEAR(turn.geodesic, (hole ? -360.0 : 360.0) / n, 1e-9) << n;
        EXPECT_NEAR(turn.total, 360.0 / n, 1e-9) << n;
        EXPECT_NEAR(turn.normal, 0.0, 1e-5) << n;
      }
      EXPECT_NEAR(geodesicSum(loop), hole ? -360.0 : 360.0, 1e-9);
    }
    EXPECT_NEAR(turning.summary(ring.vertices).geodesic, 360.0 / n, 1e-9);
    EXPECT_EQ(turning.summary(ring.vertices).zigZagShare, 0.0);
  }
}

// A regular 12-gon's fan with its centre lifted into a cone: the rim stays a planar 12-gon
// (3D turning 30 degrees) but turns within the cloth by each triangle's apex angle only, the
// rest of the 30 bending with the cloth; the sum falls by the apex's angle defect.
TEST(BoundaryTurning, AConesRimBendsWithTheCloth) {
  constexpr int n = 12;
  TriangleMesh cone;
  for (int k = 0; k < n; ++k)
    cone.vertices.emplace_back(0.2 * std::cos(2.0 * M_PI * k / n), 0.0, -0.2 * std::sin(2.0 * M_PI * k / n));
  cone.vertices.emplace_back(0.0, 0.15, 0.0);
  for (int k = 0; k < n; ++k) cone.triangles.push_back({n, k, (k + 1) % n});
  const Vec3 a = cone.vertices[0] - cone.vertices[n], b = cone.vertices[1] - cone.vertices[n];
  const double apex = std::acos(a.dot(b) / (a.norm() * b.norm())) * 180.0 / M_PI;
  const BoundaryTurning turning(cone.triangles);
  const std::vector<BoundaryTurning::Turn> loop = turning.turns(cone.vertices).front();
  for (const BoundaryTurning::Turn& turn : loop) {
    EXPECT_NEAR(turn.total, 30.0, 1e-9);
    EXPECT_NEAR(turn.geodesic, apex, 1e-9);
    EXPECT_NEAR(turn.normal, std::sqrt(30.0 * 30.0 - apex * apex), 1e-9);
  }
  EXPECT_NEAR(geodesicSum(loop), n * apex, 1e-9);
  EXPECT_LT(n * apex, 360.0);
}

// meshes::equilateralStrip's long edges are saw teeth: a node of an even row sticks out
// (two triangles, 120 degrees of cloth, +60) on one side and is set in (four, 240
// degrees, -60) on the other, and an odd row's the other way round. Rolling the strip does
// not change that (but for the chords' shortening).
TEST(BoundaryTurning, ASawToothCutAlternatesInSign) {
  constexpr int kAcross = 4, kRows = 12;
  const TriangleMesh strip = meshes::equilateralStrip(kAcross, kRows, 0.05);
  const BoundaryTurning turning(strip.triangles);
  for (const std::vector<Vec3>& x : {strip.vertices, rolled(strip.vertices, 0.3, Vec3::UnitY())}) {
    const std::vector<BoundaryTurning::Turn> loop = turning.turns(x).front();
    int teeth = 0;
    for (const BoundaryTurning::Turn& turn : loop) {
      const int i = turn.vertex % (kAcross + 1), j = turn.vertex / (kAcross + 1);
      if (j == 0 || j == kRows || (i != 0 && i != kAcross)) continue;  // an end
      EXPECT_NEAR(turn.geodesic, (j % 2 == 0) == (i == 0) ? 60.0 : -60.0, 0.5) << i << " " << j;
      ++teeth;
    }
    EXPECT_EQ(teeth, 2 * (kRows - 1));
    // Every tooth alternates but the ends' neighbours; the corners' and the ends' turns
    // do not.
    EXPECT_GT(turning.summary(x).zigZagShare, 0.6);
  }
  EXPECT_NEAR(geodesicSum(turning.turns(strip.vertices).front()), 360.0, 1e-9);
}

// The geodesic turning moves only as far as the edges' strains allow: not at all under a
// rigid motion, within the first-order allowance under a small random stretch.
TEST(BoundaryTurning, MovesOnlyAsFarAsTheStrainsAllow) {
  const TriangleMesh ring = annulus(16, 0.1);
  const BoundaryTurning turning(ring.triangles);
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
  std::vector<Vec3> moved, stretched;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jitter(-2e-4, 2e-4);  // about 1 % of an edge
  for (const Vec3& x : ring.vertices) {
    moved.push_back(rotation * x + Vec3(0.3, -0.1, 2.0));
    stretched.push_back(x + Vec3(jitter(random), jitter(random), jitter(random)));
  }
  const std::vector<std::vector<BoundaryTurning::Turn>> rest = turning.turns(ring.vertices);
  for (const std::vector<Vec3>* x : {&moved, &stretched}) {
    const std::vector<std::vector<BoundaryTurning::Turn>> now = turning.turns(*x);
    const std::vector<double> allowed = turning.geodesicStrainAllowance(ring.vertices, *x);
    size_t k = 0;
    for (size_t l = 0; l < now.size(); ++l)
      for (size_t v = 0; v < now[l].size(); ++v, ++k) {
        const double change = std::abs(now[l][v].geodesic - rest[l][v].geodesic);
        if (x == &moved) {
          EXPECT_LT(allowed[k], 1e-9);
        }
        EXPECT_LE(change, allowed[k] + 1e-9);
      }
    EXPECT_EQ(k, allowed.size());
  }
}

// Two right triangles touching at one vertex (a bow tie, two loops through it): at that
// vertex each loop turns by 180 minus its own triangle's 90 degrees, not minus both.
TEST(BoundaryTurning, LoopsThatTouchEachTurnThroughTheirOwnCloth) {
  const std::vector<Vec3> x = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(-1, 0, 0), Vec3(0, -1, 0)};
  const BoundaryTurning turning({{0, 1, 2}, {0, 3, 4}});
  const std::vector<std::vector<BoundaryTurning::Turn>> loops = turning.turns(x);
  ASSERT_EQ(loops.size(), 2u);
  for (const std::vector<BoundaryTurning::Turn>& loop : loops) {
    for (const BoundaryTurning::Turn& turn : loop) EXPECT_NEAR(turn.geodesic, turn.vertex == 0 ? 90.0 : 135.0, 1e-9);
    EXPECT_NEAR(geodesicSum(loop), 360.0, 1e-9);
  }
}

TEST(BoundaryTurning, AClosedSurfaceHasNoBoundary) {
  const TriangleMesh ball = meshes::sphere(0.1, 16, 8);
  const BoundaryTurning::Summary summary = BoundaryTurning(ball.triangles).summary(ball.vertices);
  EXPECT_EQ(summary.vertices, 0);
  EXPECT_EQ(summary.total, 0.0);
  EXPECT_EQ(summary.zigZagShare, 0.0);
}

TEST(BoundaryTurning, MedianOfOddAndEvenCounts) {
  EXPECT_EQ(BoundaryTurning::median({3.0, 1.0, 2.0}), 2.0);
  EXPECT_EQ(BoundaryTurning::median({4.0, 1.0, 3.0, 2.0}), 2.5);
  EXPECT_EQ(BoundaryTurning::median({}), 0.0);
}
