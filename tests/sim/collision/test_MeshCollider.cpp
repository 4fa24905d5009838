// The exact collider tells inside from outside on a closed surface and pushes out
// along the nearest surface normal.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "sim/collision/MeshCollider.h"
#include "support/TestMeshes.h"

using namespace figment;

TEST(MeshCollider, SignedDistanceOnASphere) {
  const double r = 0.3;
  const MeshCollider collider(meshes::sphere(r, 64, 32));
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-0.6, 0.6);
  const double inf = std::numeric_limits<double>::infinity();
  int checked = 0;
  for (int query = 0; query < 1000; ++query) {
    const Vec3 p(coordinate(random), coordinate(random), coordinate(random));
    const double exact = p.norm() - r;
    if (std::abs(exact) < 0.01) continue;  // the tessellation differs from the sphere near it
    Contact contact;
    const bool touching = collider.contact(p, 0.0, inf, contact);
    EXPECT_EQ(touching, exact < 0.0) << p.transpose();
    EXPECT_NEAR(contact.distance, exact, 0.003) << p.transpose();
    if (p.norm() > 0.05) {
      EXPECT_GT(contact.normal.dot(p.normalized()), 0.95);
    }
    ++checked;
  }
  EXPECT_GT(checked, 900);
}

TEST(MeshCollider, ClearanceCountsAsContact) {
  const MeshCollider collider(meshes::sphere(0.3, 64, 32));
  Contact contact;
  EXPECT_TRUE(collider.contact(Vec3(0, 0.302, 0), 0.005, 1.0, contact));
  EXPECT_FALSE(collider.contact(Vec3(0, 0.31, 0), 0.005, 1.0, contact));
  EXPECT_GT(contact.distance, 0.0);
}

// A sphere with its cap cut off (open above y = 0.05), as an exact part is open at its cut.
TEST(MeshCollider, AnOpenEdgeSaysNothingOfInsideWhenAskedTo) {
  const TriangleMesh sphere = meshes::sphere(0.1, 48, 24);
  TriangleMesh cut = sphere;
  cut.triangles.clear();
  for (const Triangle& t : sphere.triangles)
    if ((sphere.vertices[t[0]] + sphere.vertices[t[1]] + sphere.vertices[t[2]]).y() / 3.0 < 0.05)
      cut.triangles.push_back(t);
  const MeshCollider byPseudoNormal(cut), openOutside(cut, OpenEdges::Outside);
  const double inf = std::numeric_limits<double>::infinity();
  Contact c;
  // Above the cut, nearest the rim: the rim's one face calls it inside, which says
  // nothing about the (missing) cap; asked to, the collider calls it outside.
  const Vec3 aboveCut(0.0, 0.08, 0.0);
  byPseudoNormal.contact(aboveCut, 0.0, inf, c);
  EXPECT_LT(c.distance, 0.0);
  EXPECT_FALSE(openOutside.contact(aboveCut, 0.0, inf, c));
  EXPECT_NEAR(c.distance, std::hypot(0.1 * std::sqrt(0.75), 0.03), 0.01);
  // Below the cut, nearest a face: inside either way.
  for (const MeshCollider* collider : {&byPseudoNormal, &openOutside}) {
    ASSERT_TRUE(collider->contact(Vec3(0.0, -0.05, 0.0), 0.0, inf, c));
    EXPECT_NEAR(c.distance, -0.05, 2e-3);
  }
}

TEST(MeshCollider, AMovedCopyAnswersAsOneBuiltAnewOnTheMovedSurface) {
  const TriangleMesh ball = meshes::sphere(0.1);
  TriangleMesh moved = ball;
  for (Vec3& v : moved.vertices) v = Vec3(1.5 * v.x(), v.y() + 0.2, v.z());
  const MeshCollider original(ball, OpenEdges::Outside);
  const MeshCollider copy(original, moved.vertices);
  const MeshCollider fresh(moved, OpenEdges::Outside);
  for (const Vec3& p : {Vec3(0.14, 0.2, 0.0), Vec3(0.0, 0.31, 0.0), Vec3(0.05, 0.25, 0.02), Vec3(0.3, 0.0, 0.1)}) {
    Contact a, b;
    EXPECT_EQ(copy.contact(p, 0.01, 1.0, a), fresh.contact(p, 0.01, 1.0, b));
    EXPECT_EQ(a.distance, b.distance);
    EXPECT_EQ(a.normal, b.normal);
    EXPECT_EQ(a.surfacePoint, b.surfacePoint);
  }
  // Refused by the collider's own check, before a tree is built over too few vertices.
  try {
    MeshCollider shortOfVertices(original, {Vec3::Zero()});
    FAIL() << "a surface of 1 vertex was taken";
  } catch (const std::invalid_argument& error) {
    EXPECT_EQ(std::string(error.what()),
              "MeshCollider: 1 vertices for a surface of " + std::to_string(ball.vertices.size()));
  }
}
