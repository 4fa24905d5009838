// Plane sections as connected pieces (sim/body/SectionLoops.h), on prisms whose sections
// are known: a closed N-gon prism cut across is one piece with N points on the circle.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/body/SectionLoops.h"

namespace test_SectionLoops {

using namespace figment;

namespace {

// A closed prism along y from 0 to `height` over the regular n-gon of radius r round `centre`
// (x, z), its caps fanned from their centres.
TriangleMesh prism(int n, double r, double height, const Eigen::Vector2d& centre = Eigen::Vector2d::Zero()) {
  TriangleMesh m;
  for (int ring = 0; ring < 2; ++ring)
    for (int i = 0; i < n; ++i) {
      const double a = 2 * std::numbers::pi * i / n;
      m.vertices.emplace_back(centre.x() + r * std::cos(a), ring * height, centre.y() + r * std::sin(a));
    }
  m.vertices.emplace_back(centre.x(), 0, centre.y());
  m.vertices.emplace_back(centre.x(), height, centre.y());
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    m.triangles.push_back({i, n + j, j});
    m.triangles.push_back({i, n + i, n + j});
    m.triangles.push_back({2 * n, i, j});
    m.triangles.push_back({2 * n + 1, n + j, n + i});
  }
  return m;
}

TriangleMesh joined(TriangleMesh a, const TriangleMesh& b) {
  const int offset = int(a.vertices.size());
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (Triangle t : b.triangles) a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  return a;
}

}  // namespace

TEST(SectionLoops, APrismCutAcrossIsOnePieceOnItsCircle) {
  const TriangleMesh m = prism(24, 0.1, 1.0);
  const std::vector<SectionLoop> loops = HorizontalSections(m).at(0.37);
  ASSERT_EQ(loops.size(), 1u);
  // each side's upright edge and its diagonal, once each: the uprights' crossings on the
  // circle, the diagonals' on the side's chord, no nearer than r cos(pi / n)
  EXPECT_EQ(loops[0].points.size(), 48u);
  int onCircle = 0;
  for (const Vec3& p : loops[0].points) {
    const double r = std::hypot(p.x(), p.z());
    EXPECT_GE(r, 0.1 * std::cos(std::numbers::pi / 24) - 1e-12);
    EXPECT_LE(r, 0.1 + 1e-12);
    onCircle += std::abs(r - 0.1) < 1e-12;
    EXPECT_NEAR(p.y(), 0.37, 1e-12);
  }
  EXPECT_EQ(onCircle, 24);
}

TEST(SectionLoops, TwoPrismsCloserThanAnEdgeStayTwoPieces) {
  // 1 mm apart: proximity alone would merge them; only shared triangles join crossings
  const TriangleMesh m = joined(prism(16, 0.1, 1.0), prism(16, 0.1, 1.0, Eigen::Vector2d(0.201, 0)));
  EXPECT_EQ(HorizontalSections(m).at(0.5).size(), 2u);
  EXPECT_EQ(sectionLoops(m, Vec3(0, 0.5, 0), Vec3(0, 1, 0)).size(), 2u);
  EXPECT_TRUE(HorizontalSections(m).at(1.5).empty());  // above both
}

TEST(SectionLoops, AnyPlaneAgreesWithTheHorizontalOne) {
  const TriangleMesh m = prism(20, 0.1, 1.0);
  const auto a = HorizontalSections(m).at(0.25);
  const auto b = sectionLoops(m, Vec3(5, 0.25, -3), Vec3(0, 2, 0));  // any point on the plane, any length
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(a[0].points.size(), b[0].points.size());
  EXPECT_NEAR((a[0].centroid() - b[0].centroid()).norm(), 0.0, 1e-12);
  EXPECT_THROW(sectionLoops(m, Vec3::Zero(), Vec3::Zero()), std::invalid_argument);
}

}  // namespace test_SectionLoops
