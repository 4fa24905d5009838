// A group of collision bodies collides as their union, and a group that cannot be one is
// refused naming the entry: itself, a node that is no collision body, or nothing at all.
#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>
#include <string>

#include "nodes/body/CollisionGroup.h"
#include "sim/collision/Collider.h"
#include "support/Refusal.h"
#include "support/SceneTestSupport.h"
#include "support/TempDir.h"

using namespace figment::test;

namespace {

// cubeObj()'s unit cube moved up by `dy` (m).
std::string raisedCube(double dy) {
  std::istringstream in(cubeObj());
  std::string out, line;
  while (std::getline(in, line)) {
    if (line.rfind("v ", 0) == 0) {
      std::istringstream v(line.substr(2));
      double x, y, z;
      v >> x >> y >> z;
      line = "v " + std::to_string(x) + " " + std::to_string(y + dy) + " " + std::to_string(z);
    }
    out += line + "\n";
  }
  return out;
}

class CollisionGroupTest : public testing::Test {
 protected:
  void SetUp() override { initCoin(); }
  static std::string refusal(const CollisionGroup& group) {
    return figment::test::refusal([&] { group.bodyCollider(); });
  }
};

TEST_F(CollisionGroupTest, CollidesWithEachOfItsBodies) {
  const TempDir dir;
  const std::string low = dir.file("low.obj", cubeObj()), high = dir.file("high.obj", raisedCube(2));
  SceneRoot root = readString("#Inventor V2.1 ascii\nSeparator {\n  DEF Low MeshFile { fileName \"" + low +
                              "\" }\n  DEF High MeshFile { fileName \"" + high +
                              "\" }\n  DEF Both CollisionGroup { body USE Low layers [ USE High ] }\n}\n");
  ASSERT_TRUE(root);
  const CollisionGroup* group = find<CollisionGroup>(root.get(), "Both");
  ASSERT_NE(group, nullptr);
  const auto collider = group->bodyCollider();
  figment::Contact contact{};
  EXPECT_TRUE(collider->contact(figment::Vec3(0.5, 0.5, 0.5), 0.01, 1.0, contact));   // inside the low cube
  EXPECT_TRUE(collider->contact(figment::Vec3(0.5, 2.5, 0.5), 0.01, 1.0, contact));   // inside the high one
  EXPECT_FALSE(collider->contact(figment::Vec3(0.5, 1.5, 0.5), 0.01, 1.0, contact));  // between them
  EXPECT_EQ(group->describeBody().counts, (std::vector<std::pair<std::string, int>>{{"bodies", 2}}));
}

TEST_F(CollisionGroupTest, RefusesWhatCannotBeABodyNamingTheEntry) {
  SceneRoot root = readString(
      "#Inventor V2.1 ascii\nSeparator {\n  DEF Box Cube { }\n  DEF Empty CollisionGroup { }\n"
      "  DEF Odd CollisionGroup { layers [ USE Box ] }\n}\n");
  ASSERT_TRUE(root);
  EXPECT_EQ(refusal(*find<CollisionGroup>(root.get(), "Empty")), "CollisionGroup 'Empty': body and layers are empty");
  EXPECT_EQ(refusal(*find<CollisionGroup>(root.get(), "Odd")),
            "CollisionGroup 'Odd': layers[0] is Cube, not a collision body (Mannequin, MeshFile, GarmentSurface, "
            "CollisionGroup)");
  CollisionGroup* self = find<CollisionGroup>(root.get(), "Empty");
  self->layers.setValue(self);
  EXPECT_EQ(refusal(*self), "CollisionGroup 'Empty': layers[0] is the group itself");
  self->layers.setNum(0);
}

}  // namespace
