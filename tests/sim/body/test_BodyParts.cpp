// A body cut into its skeleton's parts: a two-bone arm of two boxes, one round each bone,
// each triangle to the bone it surrounds (an end face towards the other bone included), each
// vertex to the part of most of its triangles.
#include <gtest/gtest.h>

#include <vector>

#include "sim/body/BodyParts.h"
#include "support/ArmSkeleton.h"
#include "support/BoxFigure.h"

using namespace figment;

namespace {

// A box round each bone of test::armSkeleton(), 0.2 m apart.
TriangleMesh twoBoxes() {
  TriangleMesh mesh;
  mannequin::appendBox(mesh, {{0.1, -0.1, -0.1}, {0.9, 0.1, 0.1}});  // 12 triangles round the upper arm
  mannequin::appendBox(mesh, {{1.1, -0.1, -0.1}, {1.9, 0.1, 0.1}});  // and 12 round the forearm
  return mesh;
}

TEST(BodyParts, EachTriangleGoesToTheBoneItSurrounds) {
  const std::vector<int> parts = assignTriangles(twoBoxes(), test::armSkeleton());
  ASSERT_EQ(parts.size(), 24u);
  for (size_t t = 0; t < parts.size(); ++t) EXPECT_EQ(parts[t], t < 12 ? 0 : 1) << t;
}

TEST(BodyParts, VerticesTakeTheirTrianglesPart) {
  const TriangleMesh body = twoBoxes();
  std::vector<int> triangleParts(24, 0);
  for (int t = 12; t < 24; ++t) triangleParts[t] = 1;
  TriangleMesh withUnused = body;
  withUnused.vertices.push_back(Vec3(5, 5, 5));  // no triangle uses it
  const std::vector<int> vertices = vertexParts(withUnused, triangleParts, 2);
  ASSERT_EQ(vertices.size(), body.vertices.size() + 1);
  EXPECT_EQ(vertices.front(), 0);
  EXPECT_EQ(vertices[body.vertices.size() - 1], 1);
  EXPECT_EQ(vertices.back(), -1);
}

TEST(BodyParts, SplitNamesEachPartWithItsBoneAndTriangles) {
  const std::vector<PartMesh> parts = splitIntoParts(twoBoxes(), test::armSkeleton());
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0].name, "upperArm");
  EXPECT_EQ(parts[1].name, "forearm");
  EXPECT_EQ(parts[0].mesh.triangles.size(), 12u);
  EXPECT_EQ(parts[1].mesh.triangles.size(), 12u);
  EXPECT_EQ(parts[1].from, Vec3(1, 0, 0));
  EXPECT_EQ(parts[1].to, Vec3(2, 0, 0));
  for (const Vec3& v : parts[1].mesh.vertices) EXPECT_GT(v.x(), 1.0);
}

}  // namespace
