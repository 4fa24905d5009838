// The skin's coarse parts by the rig (sim/body/SkinParts.h): bone names to parts, each
// vertex in its heaviest bone's part, each triangle in its vertices' majority part. On
// MakeHuman's own rig: tests/io/scenarios/test_MeasuredBodies.cpp.
#include <gtest/gtest.h>

#include <algorithm>

#include "sim/body/SkinParts.h"

namespace test_SkinParts {

using namespace figment;

namespace {

int part(const std::string& name) {
  const auto& names = skinPartNames();
  return int(std::find(names.begin(), names.end(), name) - names.begin());
}

RigBone bone(const std::string& name, int parent, std::vector<std::pair<int, double>> weights) {
  RigBone b;
  b.name = name;
  b.parent = parent;
  b.head.vertices = {0};
  b.tail.vertices = {1};
  b.weights = std::move(weights);
  return b;
}

}  // namespace

TEST(SkinParts, BonesGroupIntoTheirParts) {
  EXPECT_EQ(skinPartOfBone("spine03"), part("trunk"));
  EXPECT_EQ(skinPartOfBone("pelvis.L"), part("trunk"));
  EXPECT_EQ(skinPartOfBone("breast.R"), part("trunk"));
  EXPECT_EQ(skinPartOfBone("neck02"), part("head"));
  EXPECT_EQ(skinPartOfBone("oris03.L"), part("head"));
  EXPECT_EQ(skinPartOfBone("shoulder01.L"), part("left upper arm"));
  EXPECT_EQ(skinPartOfBone("upperarm02.R"), part("right upper arm"));
  EXPECT_EQ(skinPartOfBone("lowerarm01.L"), part("left forearm"));
  EXPECT_EQ(skinPartOfBone("finger3-2.R"), part("right hand"));
  EXPECT_EQ(skinPartOfBone("upperleg01.L"), part("left thigh"));
  EXPECT_EQ(skinPartOfBone("lowerleg02.R"), part("right lower leg"));
  EXPECT_EQ(skinPartOfBone("toe1-1.L"), part("left foot"));
  EXPECT_EQ(skinPartNames().size(), 14u);
}

TEST(SkinParts, ATriangleIsInItsVerticesMajorityPart) {
  // file vertices 0..4; the skin is file vertices 1..4 (0 is helper geometry)
  HumanBase base;
  base.fileVertexCount = 5;
  base.fileIndex = {1, 2, 3, 4};
  base.skin.vertices.assign(4, Vec3::Zero());
  base.skin.triangles = {{0, 1, 2}, {1, 2, 3}};
  // vertex 1 thigh only; 2 mostly thigh; 3 and 4 mostly trunk
  const HumanRig rig({bone("root", -1, {{0, 1.0}, {2, 0.3}, {3, 0.9}, {4, 0.6}}),
                      bone("upperleg01.L", 0, {{1, 1.0}, {2, 0.7}, {3, 0.1}, {4, 0.4}})},
                     5);
  EXPECT_EQ(skinTriangleParts(rig, base), (std::vector<int>{part("left thigh"), part("trunk")}));
  base.fileVertexCount = 6;
  EXPECT_THROW(skinTriangleParts(rig, base), std::invalid_argument);
}

}  // namespace test_SkinParts
