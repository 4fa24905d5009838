// GarmentCode's own patterns (tests/io/data/patterns: a T-shirt, a pencil skirt with darts,
// a circle skirt) read and cut into cloth at 2 cm: what the sewing will rely on, on data
// nobody drew for the test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "io/PatternFile.h"
#include "sim/pattern/EdgeCurves.h"
#include "sim/pattern/PatternCutting.h"

using namespace figment;

namespace {

constexpr double kSpacing = 0.02;  // m

std::vector<std::filesystem::path> patternFiles() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(FIGMENT_SOURCE_DIR) + "/tests/io/data/patterns")) {
    if (entry.path().string().ends_with("_specification.json")) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

double angle(const Vec2& u, const Vec2& v) {
  return std::acos(std::clamp(u.dot(v) / (u.norm() * v.norm()), -1.0, 1.0));
}

}  // namespace

// GarmentCode places a garment's panels around the body's vertical axis (x = z = 0), each
// with its right side out: every triangle's normal points away from that axis.
TEST(CutPatterns, EveryTriangleFacesAwayFromTheBody) {
  const auto files = patternFiles();
  ASSERT_EQ(files.size(), 3u);
  for (const auto& file : files) {
    SCOPED_TRACE(file.filename().string());
    const UnsewnGarment garment = cutPattern(readPatternFile(file.string()), kSpacing);
    ASSERT_FALSE(garment.placed.triangles.empty());
    int inward = 0;
    for (const Triangle& t : garment.placed.triangles) {
      const Vec3 &a = garment.placed.vertices[t[0]], &b = garment.placed.vertices[t[1]],
                 &c = garment.placed.vertices[t[2]];
      const Vec3 centre = (a + b + c) / 3.0;
      inward += (b - a).cross(c - a).dot(Vec3(centre.x(), 0.0, centre.z())) <= 0.0;
    }
    EXPECT_EQ(inward, 0);
  }
}

// Each stitch pairs all its edges' nodes (a dart all but its tip), and in the direction that
// brings them together: the other order would pair the top of a side seam with its bottom.
// Where a seam lies symmetric to that swap (a shoulder straight across the gap) the two are
// equal, so the chosen one may be farther by rounding: 1 mm on average.
TEST(CutPatterns, StitchesPairTheirEdgesEndToEnd) {
  for (const auto& file : patternFiles()) {
    SCOPED_TRACE(file.filename().string());
    const SewingPattern pattern = readPatternFile(file.string());
    const UnsewnGarment garment = cutPattern(pattern, kSpacing);
    const auto segments = edgeSegments(pattern, kSpacing);
    std::map<int, std::vector<std::array<int, 2>>> byStitch;
    for (size_t i = 0; i < garment.seams.size(); ++i) byStitch[garment.seamStitch[i]].push_back(garment.seams[i]);
    for (int s = 0; s < static_cast<int>(pattern.stitches.size()); ++s) {
      const Stitch& stitch = pattern.stitches[s];
      const int n = segments[stitch.first.panel][stitch.first.edge];
      ASSERT_EQ(n, segments[stitch.second.panel][stitch.second.edge]);
      const auto& pairs = byStitch[s];
      if (stitch.first.panel == stitch.second.panel) {
        EXPECT_EQ(pairs.size(), static_cast<size_t>(n)) << "dart, stitch " << s;
        continue;
      }
      ASSERT_EQ(pairs.size(), static_cast<size_t>(n + 1)) << "stitch " << s;
      double chosen = 0.0, swapped = 0.0;
      for (int k = 0; k <= n; ++k) {
        chosen += (garment.placed.vertices[pairs[k][0]] - garment.placed.vertices[pairs[k][1]]).norm();
        swapped += (garment.placed.vertices[pairs[k][0]] - garment.placed.vertices[pairs[n - k][1]]).norm();
      }
      EXPECT_LE(chosen / (n + 1), swapped / (n + 1) + 1e-3) << "stitch " << s;
    }
  }
}

// The lattice's density (one node per sqrt(3)/2 h^2, plus (1 - 1/sqrt(3)) per h of outline,
// as test_PanelMesh derives it, within 0.2 per h of outline), and no sliver but where the
// pattern makes one: GarmentCode's outlines have edges far shorter than 2 cm (6 mm in this
// T-shirt's front and sleeves, 4.6 mm in the smallest size's), kept as they are, and a
// triangle over such an edge to nodes 2 cm away has an angle of roughly their ratio
// (measured: 13.5 degrees here, 12.8 on the smallest T-shirt, 23.7 on the skirts); 10
// degrees is the bound such edges allow.
TEST(CutPatterns, NodesAsDenseAsTheLatticeWithoutSlivers) {
  for (const auto& file : patternFiles()) {
    SCOPED_TRACE(file.filename().string());
    const SewingPattern pattern = readPatternFile(file.string());
    const UnsewnGarment garment = cutPattern(pattern, kSpacing);
    double area = 0.0, smallest = std::numbers::pi;
    for (const Triangle& t : garment.placed.triangles) {
      const Vec2 &a = garment.flat[t[0]], &b = garment.flat[t[1]], &c = garment.flat[t[2]];
      area += 0.5 * std::abs((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
      smallest = std::min({smallest, angle(b - a, c - a), angle(c - b, a - b), angle(a - c, b - c)});
    }
    double perimeter = 0.0;
    for (const Panel& panel : pattern.panels) {
      for (int k = 0; k < static_cast<int>(panel.edges.size()); ++k) perimeter += edgeLength(panel, k);
    }
    const double h = kSpacing;
    const double expected = area / (std::sqrt(3.0) / 2.0 * h * h) + (1.0 - 1.0 / std::sqrt(3.0)) * perimeter / h;
    EXPECT_NEAR(static_cast<double>(garment.flat.size()), expected, 0.2 * perimeter / h);
    EXPECT_GE(smallest, 10.0 * std::numbers::pi / 180.0);
  }
}
