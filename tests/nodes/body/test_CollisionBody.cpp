// A collision body is an interface: MeshFile and Mannequin provide it, other nodes do
// not, and a ClothEngine asks only the interface.

#include <Inventor/nodes/SoCube.h>
#include <gtest/gtest.h>

#include <stdexcept>

#include "nodes/body/CollisionBody.h"
#include "nodes/body/Mannequin.h"
#include "nodes/body/MeshFile.h"
#include "support/SceneTestSupport.h"
#include "support/TPoseSkeleton.h"

using namespace figment::test;

namespace {

class CollisionBodyTest : public ::testing::Test {
 protected:
  void SetUp() override { initCoin(); }
};

}  // namespace

TEST_F(CollisionBodyTest, MeshFileAndMannequinAreCollisionBodiesACubeIsNot) {
  SceneRoot root = readString(std::string("#Inventor V2.1 ascii\nSeparator {\n  DEF Empty MeshFile { }\n"
                                          "  DEF Model Mannequin {\n") +
                              kTPoseJoints + kForearmCapsule + "  }\n  DEF Box Cube { }\n}\n");
  ASSERT_TRUE(root);
  EXPECT_NE(figment::asCollisionBody(find<MeshFile>(root.get(), "Empty")), nullptr);
  EXPECT_NE(figment::asCollisionBody(find<Mannequin>(root.get(), "Model")), nullptr);
  EXPECT_EQ(figment::asCollisionBody(find<SoCube>(root.get(), "Box")), nullptr);
  EXPECT_EQ(figment::asCollisionBody(nullptr), nullptr);
}

TEST_F(CollisionBodyTest, AMeshFileWithoutAMeshSaysSo) {
  SceneRoot root = readString("#Inventor V2.1 ascii\nSeparator { DEF Empty MeshFile { } }\n");
  ASSERT_TRUE(root);
  const figment::CollisionBody* body = figment::asCollisionBody(find<MeshFile>(root.get(), "Empty"));
  ASSERT_NE(body, nullptr);
  try {
    body->bodyCollider();
    FAIL() << "an empty MeshFile has no collider";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "MeshFile 'Empty' has no mesh");
  }
  EXPECT_EQ(body->describeBody().kind, "mesh");
  EXPECT_TRUE(body->describeBody().counts.empty());
}

TEST_F(CollisionBodyTest, AMannequinCountsItsVolumesByKind) {
  SceneRoot root = readString(std::string("#Inventor V2.1 ascii\nSeparator {\n  DEF Model Mannequin {\n") +
                              kTPoseJoints + kForearmCapsule + "  }\n}\n");
  ASSERT_TRUE(root);
  const figment::CollisionBody* body = figment::asCollisionBody(find<Mannequin>(root.get(), "Model"));
  ASSERT_NE(body, nullptr);
  EXPECT_NE(body->bodyCollider(), nullptr);
  const figment::CollisionBody::Description description = body->describeBody();
  EXPECT_EQ(description.kind, "mannequin");
  using Count = std::pair<std::string, int>;
  EXPECT_EQ(description.counts,
            (std::vector<Count>{{"capsule_volumes", 1}, {"radial_volumes", 0}, {"exact_parts", 0}}));
}
