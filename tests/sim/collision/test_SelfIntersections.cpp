// Crossing triangles (sim/collision/SelfIntersections.h): analytic pairs, closed surfaces
// that do not cross themselves, two that cross each other, and the BVH's pairs against
// testing every pair.
#include <gtest/gtest.h>

#include "sim/collision/SelfIntersections.h"
#include "support/TestMeshes.h"

using namespace figment;

namespace {

TriangleMesh joined(TriangleMesh a, const TriangleMesh& b) {
  const int offset = int(a.vertices.size());
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (Triangle t : b.triangles) a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  return a;
}

std::vector<TrianglePair> everyPair(const TriangleMesh& m) {
  std::vector<TrianglePair> pairs;
  for (int s = 0; s < int(m.triangles.size()); ++s)
    for (int t = s + 1; t < int(m.triangles.size()); ++t) {
      const Triangle &a = m.triangles[s], &b = m.triangles[t];
      bool shared = false;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) shared = shared || a[i] == b[j];
      const auto& v = m.vertices;
      if (!shared && trianglesCross(v[a[0]], v[a[1]], v[a[2]], v[b[0]], v[b[1]], v[b[2]])) pairs.emplace_back(s, t);
    }
  return pairs;
}

}  // namespace

TEST(SelfIntersections, TrianglesCrossWhenAnEdgePassesThroughTheOther) {
  const Vec3 a0(0, 0, 0), a1(1, 0, 0), a2(0, 1, 0);  // in z = 0
  // a triangle standing through the first's interior: two of its edges pierce it
  EXPECT_TRUE(trianglesCross(a0, a1, a2, Vec3(0.2, 0.2, -1), Vec3(0.3, 0.2, 1), Vec3(0.25, 0.3, 1)));
  // the first's edge through the second's interior (the second's edges all miss the first)
  EXPECT_TRUE(trianglesCross(a0, a1, a2, Vec3(0.5, -1, -1), Vec3(0.5, -1, 1), Vec3(0.5, 2, 0)));
  // the same triangle moved off the first's plane, and one beside it
  EXPECT_FALSE(trianglesCross(a0, a1, a2, Vec3(0.2, 0.2, 0.1), Vec3(0.3, 0.2, 1), Vec3(0.25, 0.3, 1)));
  EXPECT_FALSE(trianglesCross(a0, a1, a2, Vec3(2, 2, -1), Vec3(3, 2, 1), Vec3(2.5, 3, 1)));
  // touching: a vertex resting on the face, and a coplanar overlap, do not count
  EXPECT_FALSE(trianglesCross(a0, a1, a2, Vec3(0.2, 0.2, 0), Vec3(0.3, 0.2, 1), Vec3(0.25, 0.3, 1)));
  EXPECT_FALSE(trianglesCross(a0, a1, a2, Vec3(0.1, 0.1, 0), Vec3(2, 0.1, 0), Vec3(0.1, 2, 0)));
  // the order of the two does not matter
  EXPECT_TRUE(trianglesCross(Vec3(0.2, 0.2, -1), Vec3(0.3, 0.2, 1), Vec3(0.25, 0.3, 1), a0, a1, a2));
}

TEST(SelfIntersections, AClosedSphereDoesNotCrossItself) {
  EXPECT_TRUE(selfIntersections(meshes::sphere(0.3, 40, 20)).empty());
  // two spheres apart, each closed: still none
  EXPECT_TRUE(selfIntersections(joined(meshes::sphere(0.3), meshes::sphere(0.2, 24, 12, Vec3(0.6, 0, 0)))).empty());
}

TEST(SelfIntersections, TwoSpheresThroughEachOtherCrossAlongTheirCircle) {
  const TriangleMesh big = meshes::sphere(0.3, 40, 20);
  const TriangleMesh m = joined(big, meshes::sphere(0.2, 24, 12, Vec3(0.25, 0.1, 0)));
  const std::vector<TrianglePair> pairs = selfIntersections(m);
  ASSERT_FALSE(pairs.empty());
  EXPECT_EQ(pairs, everyPair(m));  // the BVH's candidates miss none
  // every pair is one triangle of each sphere, and both lie near the circle where they meet
  // (on both spheres: |p| = 0.3 and |p - c| = 0.2), within an edge's length
  const int firstOfSmall = int(big.triangles.size());
  const Vec3 c(0.25, 0.1, 0);
  for (const auto& [s, t] : pairs) {
    EXPECT_LT(s, firstOfSmall);
    EXPECT_GE(t, firstOfSmall);
    for (const int k : {s, t}) {
      const Vec3 p =
          (m.vertices[m.triangles[k][0]] + m.vertices[m.triangles[k][1]] + m.vertices[m.triangles[k][2]]) / 3;
      EXPECT_NEAR(p.norm(), 0.3, 0.05);
      EXPECT_NEAR((p - c).norm(), 0.2, 0.05);
    }
  }
}

TEST(SelfIntersections, CrossingLabelsNameEachPairOfPartsOnce) {
  // labels: triangles 0, 1 part 0; 2 part 1; 3 part 2
  const std::vector<int> labels = {0, 0, 1, 2};
  EXPECT_EQ(crossingLabels({{0, 1}}, labels), (std::vector<std::pair<int, int>>{}));  // a fold within a part
  EXPECT_EQ(crossingLabels({{0, 2}, {1, 2}, {2, 3}, {0, 3}}, labels),
            (std::vector<std::pair<int, int>>{{0, 1}, {0, 2}, {1, 2}}));
  EXPECT_THROW(crossingLabels({{0, 4}}, labels), std::out_of_range);
}
