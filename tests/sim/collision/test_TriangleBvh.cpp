// The BVH's closest points match testing every triangle.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <string>

#include "sim/collision/TriangleBvh.h"
#include "support/TestMeshes.h"

using namespace figment;

TEST(TriangleBvh, ClosestPointOnTriangleFindsEachFeature) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_EQ(closestPointOnTriangle(Vec3(0.2, 0.2, 1), a, b, c).feature, TriangleFeature::Face);
  EXPECT_NEAR(closestPointOnTriangle(Vec3(0.2, 0.2, 1), a, b, c).distanceSquared, 1.0, 1e-15);
  EXPECT_EQ(closestPointOnTriangle(Vec3(-1, -1, 0), a, b, c).feature, TriangleFeature::Vertex0);
  EXPECT_EQ(closestPointOnTriangle(Vec3(2, -0.1, 0), a, b, c).feature, TriangleFeature::Vertex1);
  EXPECT_EQ(closestPointOnTriangle(Vec3(0.5, -1, 0), a, b, c).feature, TriangleFeature::Edge01);
  EXPECT_EQ(closestPointOnTriangle(Vec3(1, 1, 0), a, b, c).feature, TriangleFeature::Edge12);
  EXPECT_EQ(closestPointOnTriangle(Vec3(-1, 0.5, 0), a, b, c).feature, TriangleFeature::Edge20);
  EXPECT_TRUE(closestPointOnTriangle(Vec3(1, 1, 0), a, b, c).point.isApprox(Vec3(0.5, 0.5, 0)));
}

TEST(TriangleBvh, MatchesBruteForceOnRandomQueries) {
  // A lumpy closed surface: two overlapping spheres, so the tree has real work to do.
  TriangleMesh mesh = meshes::sphere(0.3, 40, 20);
  const TriangleMesh other = meshes::sphere(0.2, 24, 12, Vec3(0.25, 0.1, 0));
  const int offset = static_cast<int>(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), other.vertices.begin(), other.vertices.end());
  for (Triangle t : other.triangles) mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  const TriangleBvh bvh(mesh);
  std::mt19937 random(42);
  std::uniform_real_distribution<double> coordinate(-0.8, 0.8);
  for (int query = 0; query < 2000; ++query) {
    const Vec3 p(coordinate(random), coordinate(random), coordinate(random));
    const ClosestPoint fast = bvh.closest(p);
    const ClosestPoint reference = bvh.closestBruteForce(p);
    ASSERT_GE(fast.triangle, 0);
    EXPECT_NEAR(fast.distanceSquared, reference.distanceSquared, 1e-14) << "query " << query;
    EXPECT_LT((fast.point - reference.point).norm(), 1e-9) << "query " << query;
  }
}

TEST(TriangleBvh, BoundedQueryFindsNothingBeyondTheRadius) {
  const TriangleBvh bvh(meshes::sphere(0.3));
  EXPECT_LT(bvh.closest(Vec3(0, 1.0, 0), 0.5).triangle, 0);
  EXPECT_GE(bvh.closest(Vec3(0, 1.0, 0), 0.71).triangle, 0);
}

TEST(TriangleBvh, OverlappingFindsExactlyTheTrianglesWhoseBoxesMeetTheBox) {
  const TriangleMesh mesh = meshes::sphere(0.3, 40, 20);
  const TriangleBvh bvh(mesh);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-0.4, 0.4), size(0.0, 0.2);
  for (int query = 0; query < 200; ++query) {
    Bounds box;
    const Vec3 corner(coordinate(random), coordinate(random), coordinate(random));
    box.extend(corner);
    box.extend(corner + Vec3(size(random), size(random), size(random)));
    std::vector<int> found;
    bvh.overlapping(box, found);
    std::sort(found.begin(), found.end());
    std::vector<int> expected;
    for (int t = 0; t < int(mesh.triangles.size()); ++t) {
      Bounds own;
      for (int k = 0; k < 3; ++k) own.extend(mesh.vertices[mesh.triangles[t][k]]);
      if ((own.min.array() <= box.max.array()).all() && (box.min.array() <= own.max.array()).all())
        expected.push_back(t);
    }
    EXPECT_EQ(found, expected) << "query " << query;
  }
}

// A triangle naming a vertex the mesh lacks is refused by name, before any vertex is read
// (PosedSkin built its tree over a posed skin short of a vertex: ASan's heap overflow).
TEST(TriangleBvh, RefusesATriangleNamingAVertexTheMeshLacks) {
  TriangleMesh mesh = meshes::sphere(0.1, 8, 4);
  EXPECT_NO_THROW(TriangleBvh{mesh});  // the control
  const int n = static_cast<int>(mesh.vertices.size());
  mesh.triangles[5][2] = n;
  try {
    TriangleBvh bvh(mesh);
    FAIL() << "a triangle past the vertices was taken";
  } catch (const std::invalid_argument& error) {
    EXPECT_EQ(std::string(error.what()),
              "triangle 5 names vertex " + std::to_string(n) + " of a mesh of " + std::to_string(n));
  }
  mesh.triangles[5][2] = -1;
  EXPECT_THROW(TriangleBvh{mesh}, std::invalid_argument);
}
