// Patterns cut into cloth: a two-panel tube (a front and a back rectangle 20 cm apart,
// sewn at both sides) and small variations of it, where every seam pair, every normal and
// every placed triangle is known.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <stdexcept>

#include "sim/pattern/EdgeCurves.h"
#include "sim/pattern/PatternCutting.h"

namespace test_PatternCutting {

using namespace figment;

namespace {

constexpr double kWidth = 0.4, kHeight = 0.6, kGap = 0.2;  // m
constexpr double kSpacing = 0.02;                          // m

// A panel of straight edges round `corners`, edge k from corner k to corner k + 1.
Panel polygonPanel(const std::string& name, const std::vector<Vec2>& corners) {
  Panel panel;
  panel.name = name;
  panel.vertices = corners;
  for (int k = 0; k < static_cast<int>(corners.size()); ++k) {
    panel.edges.push_back({k, (k + 1) % static_cast<int>(corners.size()), {}});
  }
  return panel;
}

// The tube: the front's outline counter-clockwise in (u, v) (right side towards +z), the
// back's clockwise (right side towards -z), both unrotated, as GarmentCode places a
// skirt's panels. Front edges: 0 hem, 1 right side (up), 2 top, 3 left side (down). Back
// edges: 0 left side (up), 1 top, 2 right side (down), 3 hem.
SewingPattern tube(double backHeight = kHeight) {
  const double w = kWidth / 2;
  SewingPattern pattern;
  pattern.name = "tube";
  Panel front = polygonPanel("front", {{-w, 0}, {w, 0}, {w, kHeight}, {-w, kHeight}});
  front.translation = Vec3(0, 0.8, kGap / 2);
  Panel back = polygonPanel("back", {{-w, 0}, {-w, backHeight}, {w, backHeight}, {w, 0}});
  back.translation = Vec3(0, 0.8, -kGap / 2);
  pattern.panels = {front, back};
  pattern.stitches = {{{0, 1}, {1, 2}, false}, {{0, 3}, {1, 0}, false}};
  return pattern;
}

// The fraction of its edge's arc length at which a node lies (straight edges).
double fractionAlong(const SewingPattern& pattern, const UnsewnGarment& garment, const EdgeRef& ref, int node) {
  const Panel& panel = pattern.panels[ref.panel];
  const Vec2& start = panel.vertices[panel.edges[ref.edge].from];
  return (garment.flat[node] - start).norm() / edgeLength(panel, ref.edge);
}

// Whether `node` lies on the edge (straight, panel coordinates), within 1e-12 m.
bool onEdge(const SewingPattern& pattern, const UnsewnGarment& garment, const EdgeRef& ref, int node) {
  const Panel& panel = pattern.panels[ref.panel];
  const Vec2& s = panel.vertices[panel.edges[ref.edge].from];
  const Vec2& e = panel.vertices[panel.edges[ref.edge].to];
  const Vec2 p = garment.flat[node];
  return garment.panelOf[node] == ref.panel &&
         std::abs((e - s).x() * (p - s).y() - (e - s).y() * (p - s).x()) < 1e-12 * (e - s).norm();
}

Vec3 normalOf(const TriangleMesh& mesh, const Triangle& t) {
  const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
  return (b - a).cross(c - a).normalized();
}

}  // namespace

// 0.6 m sides at 2 cm: 30 segments, 31 pairs per side seam, each pair at one height.
TEST(PatternCutting, TubeSeamsPairNodesAtEqualHeights) {
  const SewingPattern pattern = tube();
  const UnsewnGarment garment = cutPattern(pattern, kSpacing);
  ASSERT_EQ(garment.seams.size(), 62u);
  ASSERT_EQ(garment.seamStitch.size(), garment.seams.size());
  std::set<int> nodes;
  for (size_t i = 0; i < garment.seams.size(); ++i) {
    const auto [a, b] = garment.seams[i];
    const Stitch& stitch = pattern.stitches[garment.seamStitch[i]];
    EXPECT_TRUE(onEdge(pattern, garment, stitch.first, a));
    EXPECT_TRUE(onEdge(pattern, garment, stitch.second, b));
    // Front and back face each other across the gap: same x and y, z kGap apart.
    const Vec3 gap = garment.placed.vertices[b] - garment.placed.vertices[a];
    EXPECT_NEAR(gap.x(), 0.0, 1e-12);
    EXPECT_NEAR(gap.y(), 0.0, 1e-12);
    EXPECT_NEAR(gap.z(), -kGap, 1e-12);
    nodes.insert(a);
    nodes.insert(b);
  }
  EXPECT_EQ(nodes.size(), 124u);  // every node of the four side edges, once each
  EXPECT_EQ(std::count(garment.seamStitch.begin(), garment.seamStitch.end(), 0), 31);
  EXPECT_EQ(std::count(garment.seamStitch.begin(), garment.seamStitch.end(), 1), 31);
}

// An eased seam: the back 10 % taller, so its sides are 0.66 m against the front's 0.6 m.
// Both sides get the longer one's 33 segments, and each pair lies at one fraction of both.
TEST(PatternCutting, StitchedEdgesShareTheLargerSegmentCount) {
  const SewingPattern pattern = tube(1.1 * kHeight);
  const std::vector<std::vector<int>> segments = edgeSegments(pattern, kSpacing);
  EXPECT_EQ(segments[0], (std::vector<int>{20, 33, 20, 33}));
  EXPECT_EQ(segments[1], (std::vector<int>{33, 20, 33, 20}));

  const UnsewnGarment garment = cutPattern(pattern, kSpacing);
  ASSERT_EQ(garment.seams.size(), 68u);
  for (size_t i = 0; i < garment.seams.size(); ++i) {
    const Stitch& stitch = pattern.stitches[garment.seamStitch[i]];
    const double a = fractionAlong(pattern, garment, stitch.first, garment.seams[i][0]);
    const double b = fractionAlong(pattern, garment, stitch.second, garment.seams[i][1]);
    EXPECT_NEAR(a, 1.0 - b, 1e-12);  // the second edge runs the other way
  }
}

// An edge sewn to two others (a chain a-b, b-c): all three share the largest count, so
// both stitches pair node for node.
TEST(PatternCutting, EdgeInTwoStitchesSharesOneCount) {
  SewingPattern pattern;
  pattern.panels = {polygonPanel("a", {{0, 0}, {0.1, 0}, {0.1, 0.3}, {0, 0.3}}),
                    polygonPanel("b", {{0, 0}, {0.1, 0}, {0.1, 0.5}, {0, 0.5}}),
                    polygonPanel("c", {{0, 0}, {0.1, 0}, {0.1, 0.4}, {0, 0.4}})};
  pattern.stitches = {{{0, 1}, {1, 1}, false}, {{1, 1}, {2, 1}, false}};
  const std::vector<std::vector<int>> segments = edgeSegments(pattern, kSpacing);
  for (int p = 0; p < 3; ++p) EXPECT_EQ(segments[p][1], 25) << pattern.panels[p].name;  // 0.5 m / 2 cm
  EXPECT_EQ(segments[0][3], 15);                                                        // free: its own
  EXPECT_EQ(cutPattern(pattern, kSpacing).seams.size(), 52u);
}

// GarmentCode's "right_wrong": the second edge is not reversed.
TEST(PatternCutting, SameDirectionStitchPairsNodeKWithNodeK) {
  SewingPattern pattern = tube();
  pattern.stitches[0].sameDirection = true;
  const UnsewnGarment garment = cutPattern(pattern, kSpacing);
  for (size_t i = 0; i < garment.seams.size(); ++i) {
    const Stitch& stitch = pattern.stitches[garment.seamStitch[i]];
    const double a = fractionAlong(pattern, garment, stitch.first, garment.seams[i][0]);
    const double b = fractionAlong(pattern, garment, stitch.second, garment.seams[i][1]);
    EXPECT_NEAR(a, stitch.sameDirection ? b : 1.0 - b, 1e-12);
  }
}

// The front's right side faces +z, the back's -z: out of the tube, both, although both
// panels are placed unrotated; GarmentCode tells them apart by the outline's direction.
TEST(PatternCutting, TrianglesFaceOutOfTheTube) {
  const UnsewnGarment garment = cutPattern(tube(), kSpacing);
  int front = 0, back = 0;
  for (const Triangle& t : garment.placed.triangles) {
    const Vec3 normal = normalOf(garment.placed, t);
    if (garment.panelOf[t[0]] == 0) {
      EXPECT_NEAR(normal.z(), 1.0, 1e-12);
      ++front;
    } else {
      EXPECT_NEAR(normal.z(), -1.0, 1e-12);
      ++back;
    }
  }
  EXPECT_GT(front, 0);
  EXPECT_GT(back, 0);
}

// A panel placed turned (a sleeve, 45 degrees about z, tipped 30 about x): its normals are
// the rotated panel normal, its nodes R (u, v, 0) + t, its triangles congruent to the flat
// ones (a rigid placement), and `flat` its own panel coordinates.
TEST(PatternCutting, PlacementIsRigidAndFlatKeepsPanelCoordinates) {
  SewingPattern pattern = tube();
  Panel& front = pattern.panels[0];
  front.rotation =
      (Eigen::AngleAxisd(std::numbers::pi / 6, Vec3::UnitX()) * Eigen::AngleAxisd(std::numbers::pi / 4, Vec3::UnitZ()))
          .toRotationMatrix();
  const UnsewnGarment garment = cutPattern(pattern, kSpacing);
  ASSERT_EQ(garment.flat.size(), garment.placed.vertices.size());
  ASSERT_EQ(garment.panelOf.size(), garment.placed.vertices.size());
  EXPECT_EQ(garment.panelNames, (std::vector<std::string>{"front", "back"}));
  for (size_t i = 0; i < garment.flat.size(); ++i) {
    const Panel& panel = pattern.panels[garment.panelOf[i]];
    const Vec3 expected = panel.rotation * Vec3(garment.flat[i].x(), garment.flat[i].y(), 0) + panel.translation;
    EXPECT_LT((garment.placed.vertices[i] - expected).norm(), 1e-12);
    EXPECT_LE(std::abs(garment.flat[i].x()), kWidth / 2 + 1e-12);  // inside its panel
    EXPECT_GE(garment.flat[i].y(), -1e-12);
    EXPECT_LE(garment.flat[i].y(), kHeight + 1e-12);
  }
  const Vec3 frontNormal = front.rotation * Vec3::UnitZ();
  for (const Triangle& t : garment.placed.triangles) {
    EXPECT_EQ(garment.panelOf[t[1]], garment.panelOf[t[0]]);
    EXPECT_EQ(garment.panelOf[t[2]], garment.panelOf[t[0]]);
    for (int k = 0; k < 3; ++k) {
      const double flat = (garment.flat[t[(k + 1) % 3]] - garment.flat[t[k]]).norm();
      const double placed = (garment.placed.vertices[t[(k + 1) % 3]] - garment.placed.vertices[t[k]]).norm();
      EXPECT_NEAR(placed, flat, 1e-12);
    }
    if (garment.panelOf[t[0]] == 0) {
      EXPECT_LT((normalOf(garment.placed, t) - frontNormal).norm(), 1e-9);
    }
  }
}

// A dart: a V notch in a skirt panel's waist whose two sides are sewn together. They meet
// at the tip, which is paired with itself and so left out; the other pairs are mirror
// images across the dart's axis (u = 0.25).
TEST(PatternCutting, DartPairsMirrorNodesAndLeavesOutItsTip) {
  SewingPattern pattern;
  pattern.panels = {
      polygonPanel("skirt", {{0, 0}, {0.5, 0}, {0.5, 0.4}, {0.27, 0.4}, {0.25, 0.28}, {0.23, 0.4}, {0, 0.4}})};
  pattern.stitches = {{{0, 3}, {0, 4}, false}};  // edge 3 runs down to the tip, edge 4 up from it
  const UnsewnGarment garment = cutPattern(pattern, kSpacing);
  const int n = edgeSegments(pattern, kSpacing)[0][3];
  EXPECT_EQ(n, 7);  // 0.1217 m / 2 cm
  ASSERT_EQ(garment.seams.size(), static_cast<size_t>(n));
  for (const auto& [a, b] : garment.seams) {
    ASSERT_NE(a, b);
    EXPECT_NEAR(garment.flat[a].x() - 0.25, 0.25 - garment.flat[b].x(), 1e-12);
    EXPECT_NEAR(garment.flat[a].y(), garment.flat[b].y(), 1e-12);
  }
}

TEST(PatternCutting, RejectsBadSpacing) {
  EXPECT_THROW(cutPattern(tube(), 0.0), std::invalid_argument);
  EXPECT_THROW(cutPattern(tube(), std::nan("")), std::invalid_argument);
}

TEST(PatternCutting, RejectsStitchesNamingMissingEdges) {
  SewingPattern pattern = tube();
  pattern.stitches[1].second.panel = 2;
  EXPECT_THROW(cutPattern(pattern, kSpacing), std::invalid_argument);
  pattern = tube();
  pattern.stitches[1].second.edge = 4;
  EXPECT_THROW(cutPattern(pattern, kSpacing), std::invalid_argument);
  pattern = tube();
  pattern.stitches[0].second = pattern.stitches[0].first;
  EXPECT_THROW(cutPattern(pattern, kSpacing), std::invalid_argument);
}

// A mirrored placement would turn the fabric's right side in.
TEST(PatternCutting, RejectsPlacementThatIsNotARotation) {
  SewingPattern pattern = tube();
  pattern.panels[1].rotation = Eigen::Vector3d(-1, 1, 1).asDiagonal();
  try {
    cutPattern(pattern, kSpacing);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("'back'"), std::string::npos) << error.what();
  }
}

TEST(PatternCutting, RejectsEdgesThatDoNotFormALoop) {
  SewingPattern pattern = tube();
  pattern.panels[0].edges[2].to = 0;
  EXPECT_THROW(cutPattern(pattern, kSpacing), std::invalid_argument);
}

// A panel whose outline crosses itself is named in the error.
TEST(PatternCutting, NamesThePanelWhoseOutlineCrossesItself) {
  SewingPattern pattern = tube();
  std::swap(pattern.panels[0].vertices[2], pattern.panels[0].vertices[3]);
  try {
    cutPattern(pattern, kSpacing);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("'front'"), std::string::npos) << error.what();
  }
}

}  // namespace test_PatternCutting
