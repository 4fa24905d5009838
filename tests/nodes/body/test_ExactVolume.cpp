// An exact volume is the part's own triangles: a closed cube made into a volume holds its
// centre, and a part with no triangles is refused naming the node and the part.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "nodes/body/ExactVolume.h"
#include "sim/collision/CollisionVolume.h"
#include "support/BoxFigure.h"
#include "support/SceneTestSupport.h"

using namespace figment::test;

namespace {

TEST(ExactVolume, IsThePartsTrianglesAndRefusesAPartWithout) {
  initCoin();
  SceneRoot root = readString("#Inventor V2.1 ascii\nSeparator { DEF Face ExactVolume { part \"head\" } }\n");
  ASSERT_TRUE(root);
  const ExactVolume* exact = find<ExactVolume>(root.get(), "Face");
  ASSERT_NE(exact, nullptr);
  const auto volume = exact->makeVolume(figment::mannequin::boxMesh({{0, 0, 0}, {1, 1, 1}}));
  ASSERT_NE(volume, nullptr);
  EXPECT_TRUE(volume->contains(figment::Vec3(0.5, 0.5, 0.5)));
  EXPECT_FALSE(volume->contains(figment::Vec3(1.5, 0.5, 0.5)));
  try {
    exact->makeVolume({});
    FAIL() << "a part without triangles was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "ExactVolume 'Face': part = \"head\" has no triangles in the body");
  }
}

}  // namespace
