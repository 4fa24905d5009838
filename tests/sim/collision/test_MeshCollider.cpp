// The exact collider tells inside from outside on a closed surface and pushes out
// along the nearest surface normal.
#include "support/TestMeshes.h"
#include "sim/collision/MeshCollider.h"

#include <gtest/gtest.h>

#include <random>

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
