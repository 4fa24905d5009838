// Panels cut into triangles: outlines whose area and shape are known (a rectangle either
// way round, an L, a sleeve cap, a dart's notch), checked for what the cloth needs: the
// outline kept point for point, the triangles tiling it exactly, counter-clockwise, no
// slivers, as many nodes as the lattice's density says.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "sim/pattern/PanelMesh.h"

using namespace figment;

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// The smallest angle any triangle may have, on outlines without corners sharper than it:
// away from the outline the lattice's triangles are equilateral (60 degrees); next to it a
// lattice node is at least h/2 from every outline segment, and outline segments are h/2 to
// h long, so no triangle joins a short segment to a far node. Measured: 23.2 to 25.6
// degrees over these outlines at spacings from 7 to 31 mm; 20 leaves a margin.
constexpr double kMinAngle = 20.0 * kDegree;

// A closed polygon's edges, each side cut into ceil(length / h) equal segments, as the
// pattern's edge sampling cuts a straight edge.
std::vector<std::vector<Vec2>> sampledSides(const std::vector<Vec2>& corners, double h) {
  std::vector<std::vector<Vec2>> edges;
  for (size_t k = 0; k < corners.size(); ++k) {
    const Vec2& a = corners[k];
    const Vec2& b = corners[(k + 1) % corners.size()];
    const int segments = std::max(1, static_cast<int>(std::ceil((b - a).norm() / h - 1e-9)));
    std::vector<Vec2> edge;
    for (int i = 0; i < segments; ++i) edge.push_back(a + (b - a) * (double(i) / segments));
    edge.push_back(b);
    edges.push_back(edge);
  }
  return edges;
}

// A curve given by many points, resampled at ceil(length / h) segments of equal arc length
// (along the fine polyline).
std::vector<Vec2> resampled(const std::vector<Vec2>& fine, double h) {
  std::vector<double> along{0.0};
  for (size_t i = 1; i < fine.size(); ++i) along.push_back(along.back() + (fine[i] - fine[i - 1]).norm());
  const int segments = std::max(1, static_cast<int>(std::ceil(along.back() / h)));
  std::vector<Vec2> points{fine.front()};
  size_t i = 1;
  for (int s = 1; s < segments; ++s) {
    const double target = along.back() * s / segments;
    while (along[i] < target) ++i;
    const double t = (target - along[i - 1]) / (along[i] - along[i - 1]);
    points.push_back(fine[i - 1] + t * (fine[i] - fine[i - 1]));
  }
  points.push_back(fine.back());
  return points;
}

std::vector<Vec2> outlineOf(const PanelMesh& mesh) {
  return {mesh.points.begin(), mesh.points.begin() + mesh.outlineCount};
}

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

double signedArea(const std::vector<Vec2>& loop) {
  double twice = 0.0;
  for (size_t i = 0; i < loop.size(); ++i) twice += cross(loop[i], loop[(i + 1) % loop.size()]);
  return 0.5 * twice;
}

double perimeter(const std::vector<Vec2>& loop) {
  double length = 0.0;
  for (size_t i = 0; i < loop.size(); ++i) length += (loop[(i + 1) % loop.size()] - loop[i]).norm();
  return length;
}

bool inside(const std::vector<Vec2>& loop, const Vec2& p) {
  bool in = false;
  for (size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
    const Vec2 &a = loop[i], &b = loop[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < a.x() + (p.y() - a.y()) / (b.y() - a.y()) * (b.x() - a.x())) {
      in = !in;
    }
  }
  return in;
}

double triangleArea(const PanelMesh& mesh, const std::array<int, 3>& t) {
  const Vec2 &a = mesh.points[t[0]], &b = mesh.points[t[1]], &c = mesh.points[t[2]];
  return 0.5 * cross(b - a, c - a);
}

// The smallest interior angle (radians) of the triangles `which` accepts.
template <typename Which>
double minAngle(const PanelMesh& mesh, Which which) {
  double smallest = std::numbers::pi;
  for (const auto& t : mesh.triangles) {
    if (!which(t)) continue;
    for (int k = 0; k < 3; ++k) {
      const Vec2 u = mesh.points[t[(k + 1) % 3]] - mesh.points[t[k]];
      const Vec2 v = mesh.points[t[(k + 2) % 3]] - mesh.points[t[k]];
      smallest = std::min(smallest, std::acos(std::clamp(u.dot(v) / (u.norm() * v.norm()), -1.0, 1.0)));
    }
  }
  return smallest;
}

// What every panel's mesh must be, whatever its outline: the outline's points first and
// unchanged, each edge's nodes in order, the triangles counter-clockwise and inside the
// outline, tiling it exactly (areas summing to the polygon's), every outline segment the
// edge of one triangle and every other edge shared by two (one sheet, no holes, no folds),
// and as many nodes as a lattice of spacing h holds, give or take a row along the outline.
void expectTilesItsOutline(const std::vector<std::vector<Vec2>>& edges, double h, const PanelMesh& mesh) {
  std::vector<Vec2> given;
  for (const auto& edge : edges) given.insert(given.end(), edge.begin(), edge.end() - 1);
  ASSERT_EQ(mesh.outlineCount, static_cast<int>(given.size()));
  for (size_t i = 0; i < given.size(); ++i) EXPECT_EQ(mesh.points[i], given[i]) << "outline point " << i;
  ASSERT_EQ(mesh.edgeNodes.size(), edges.size());
  for (size_t k = 0; k < edges.size(); ++k) {
    ASSERT_EQ(mesh.edgeNodes[k].size(), edges[k].size()) << "edge " << k;
    for (size_t i = 0; i < edges[k].size(); ++i) EXPECT_EQ(mesh.points[mesh.edgeNodes[k][i]], edges[k][i]);
  }

  const std::vector<Vec2> outline = outlineOf(mesh);
  const double polygonArea = std::abs(signedArea(outline));
  double area = 0.0;
  std::map<std::pair<int, int>, int> edgeUse;  // directed edges
  for (const auto& t : mesh.triangles) {
    const double a = triangleArea(mesh, t);
    EXPECT_GT(a, 0.0) << "triangle " << t[0] << " " << t[1] << " " << t[2] << " is not counter-clockwise";
    area += a;
    EXPECT_TRUE(inside(outline, (mesh.points[t[0]] + mesh.points[t[1]] + mesh.points[t[2]]) / 3.0));
    for (int k = 0; k < 3; ++k) ++edgeUse[{t[k], t[(k + 1) % 3]}];
  }
  EXPECT_NEAR(area, polygonArea, 1e-9 * polygonArea);

  const int n = mesh.outlineCount;
  const bool ccw = signedArea(outline) > 0.0;
  for (int i = 0; i < n; ++i) {
    // A counter-clockwise triangle runs along a counter-clockwise outline's segment.
    const std::pair<int, int> segment = ccw ? std::pair{i, (i + 1) % n} : std::pair{(i + 1) % n, i};
    EXPECT_EQ(edgeUse[segment], 1) << "outline segment " << i;
    EXPECT_EQ(edgeUse.count({segment.second, segment.first}), 0u) << "outline segment " << i;
  }
  for (const auto& [edge, count] : edgeUse) {
    EXPECT_EQ(count, 1);
    const bool onOutline = (edge.first + 1) % n == edge.second || (edge.second + 1) % n == edge.first;
    const bool outlinePoints = edge.first < n && edge.second < n;
    if (!(onOutline && outlinePoints)) {
      EXPECT_EQ(edgeUse.count({edge.second, edge.first}), 1u);
    }
  }

  // One lattice node per sqrt(3)/2 h^2 of area, but none in the band h/2 wide along the
  // outline (P h/2 of area), which has the outline's own node per h of perimeter P instead:
  // (1 - 1/sqrt(3)) P/h more than the lattice alone. Where the lattice's rows fall against
  // the band moves that by a fraction of a row: 0.2 P/h (measured: up to 0.12 P/h).
  const double p = perimeter(outline);
  const double expected = polygonArea / (std::sqrt(3.0) / 2.0 * h * h) + (1.0 - 1.0 / std::sqrt(3.0)) * p / h;
  EXPECT_NEAR(static_cast<double>(mesh.points.size()), expected, 0.2 * p / h);
}

bool latticeOnly(const PanelMesh& mesh, const std::array<int, 3>& t) {
  return t[0] >= mesh.outlineCount && t[1] >= mesh.outlineCount && t[2] >= mesh.outlineCount;
}

}  // namespace

TEST(PanelMesh, RectangleTilesItsOutline) {
  const double h = 0.02;  // m
  const auto edges = sampledSides({{0, 0}, {0.4, 0}, {0.4, 0.6}, {0, 0.6}}, h);
  const PanelMesh mesh = meshPanel(edges, h);
  expectTilesItsOutline(edges, h, mesh);
  EXPECT_EQ(mesh.outlineCount, 100);  // 20 + 30 + 20 + 30 segments
  EXPECT_NEAR(minAngle(mesh, [&](const auto& t) { return latticeOnly(mesh, t); }), 60.0 * kDegree, 1e-6);
  EXPECT_GE(minAngle(mesh, [](const auto&) { return true; }), kMinAngle);
}

// A clockwise outline (a back panel's) still gives counter-clockwise triangles in (u, v):
// which side is the right side is the cutting's business, not the mesh's.
TEST(PanelMesh, ClockwiseOutlineGivesCounterClockwiseTriangles) {
  const double h = 0.02;
  const auto edges = sampledSides({{0, 0}, {0, 0.6}, {0.4, 0.6}, {0.4, 0}}, h);
  expectTilesItsOutline(edges, h, meshPanel(edges, h));
}

// A quadrilateral whose sides are not along the lattice's rows, at several spacings (m).
class PanelMeshSpacing : public testing::TestWithParam<double> {};

TEST_P(PanelMeshSpacing, NoSlivers) {
  const double h = GetParam();
  const auto edges = sampledSides({{0, 0}, {0.4, 0.1}, {0.3, 0.6}, {-0.1, 0.5}}, h);
  const PanelMesh mesh = meshPanel(edges, h);
  expectTilesItsOutline(edges, h, mesh);
  EXPECT_NEAR(minAngle(mesh, [&](const auto& t) { return latticeOnly(mesh, t); }), 60.0 * kDegree, 1e-6);
  EXPECT_GE(minAngle(mesh, [](const auto&) { return true; }), kMinAngle);
}

INSTANTIATE_TEST_SUITE_P(PanelMesh, PanelMeshSpacing, testing::Values(0.007, 0.013, 0.02, 0.031));

// An L (one reflex corner): the notch's triangles are erased, the reflex corner kept.
TEST(PanelMesh, LShapeTilesItsOutline) {
  const double h = 0.02;
  const auto edges = sampledSides({{0, 0}, {0.5, 0}, {0.5, 0.2}, {0.2, 0.2}, {0.2, 0.6}, {0, 0.6}}, h);
  const PanelMesh mesh = meshPanel(edges, h);
  expectTilesItsOutline(edges, h, mesh);
  EXPECT_GE(minAngle(mesh, [](const auto&) { return true; }), kMinAngle);
}

// A sleeve: straight sides and hem, and a cap that is concave near the underarms and
// convex over the shoulder, one curved edge sampled by arc length.
TEST(PanelMesh, SleeveCapTilesItsOutline) {
  const double h = 0.02, width = 0.36, height = 0.25, cap = 0.14;  // m
  std::vector<Vec2> curve;
  for (int i = 0; i <= 400; ++i) {
    const double x = width * (1.0 - i / 400.0);  // from the right underarm to the left
    const double s = (x - width / 2) / (width / 4);
    curve.emplace_back(x, height + cap * (std::exp(-s * s) - std::exp(-4.0)) / (1.0 - std::exp(-4.0)));
  }
  std::vector<std::vector<Vec2>> edges = sampledSides({{0, height}, {0, 0}, {width, 0}, {width, height}}, h);
  edges.pop_back();  // the cap closes the outline instead of the top side
  edges.push_back(resampled(curve, h));
  const PanelMesh mesh = meshPanel(edges, h);
  expectTilesItsOutline(edges, h, mesh);
  EXPECT_GE(minAngle(mesh, [](const auto&) { return true; }), kMinAngle);
}

// A dart's notch cut into a skirt panel's waist: a narrow V whose two sides a stitch will
// sew together. No triangle bridges the notch.
TEST(PanelMesh, DartNotchTilesItsOutline) {
  const double h = 0.02;
  const auto edges = sampledSides({{0, 0}, {0.5, 0}, {0.5, 0.4}, {0.27, 0.4}, {0.25, 0.28}, {0.23, 0.4}, {0, 0.4}}, h);
  const PanelMesh mesh = meshPanel(edges, h);
  expectTilesItsOutline(edges, h, mesh);
  EXPECT_GE(minAngle(mesh, [](const auto&) { return true; }), kMinAngle);
}

// A panel smaller than the spacing: no lattice node fits, the outline alone is cut.
TEST(PanelMesh, SmallPanelHasOutlineNodesOnly) {
  const double h = 0.1;
  const auto edges = sampledSides({{0, 0}, {0.05, 0}, {0.0, 0.05}}, h);
  const PanelMesh mesh = meshPanel(edges, h);
  EXPECT_EQ(mesh.points.size(), 3u);
  ASSERT_EQ(mesh.triangles.size(), 1u);
  EXPECT_GT(triangleArea(mesh, mesh.triangles[0]), 0.0);
}

TEST(PanelMesh, RejectsBadSpacing) {
  const auto edges = sampledSides({{0, 0}, {1, 0}, {0, 1}}, 0.1);
  EXPECT_THROW(meshPanel(edges, 0.0), std::invalid_argument);
  EXPECT_THROW(meshPanel(edges, -0.1), std::invalid_argument);
  EXPECT_THROW(meshPanel(edges, std::nan("")), std::invalid_argument);
}

TEST(PanelMesh, RejectsEdgesThatDoNotMeet) {
  auto edges = sampledSides({{0, 0}, {1, 0}, {0, 1}}, 0.1);
  edges[1].back() += Vec2(0.01, 0.0);
  EXPECT_THROW(meshPanel(edges, 0.1), std::invalid_argument);
}

// A bow tie: its two sides cross; CDT must not add the crossing point.
TEST(PanelMesh, RejectsOutlineThatCrossesItself) {
  const auto edges = sampledSides({{0, 0}, {1, 1}, {1, 0}, {0, 1}}, 0.1);
  EXPECT_THROW(meshPanel(edges, 0.1), std::invalid_argument);
}

// Two corners of a figure eight at the same place.
TEST(PanelMesh, RejectsOutlineThatTouchesItself) {
  const auto edges = sampledSides({{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}, {1, 2}, {1, 1}, {0, 1}}, 0.1);
  EXPECT_THROW(meshPanel(edges, 0.1), std::invalid_argument);
}

TEST(PanelMesh, RejectsTooFewPoints) {
  EXPECT_THROW(meshPanel({{{0, 0}, {1, 0}}, {{1, 0}, {0, 0}}}, 0.1), std::invalid_argument);
  EXPECT_THROW(meshPanel({}, 0.1), std::invalid_argument);
}
