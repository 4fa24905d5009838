// What every volume node shares: its label, its wireframe as its bounding box (none for an
// exact volume, which draws nothing), made again when a field changes.
#include <Inventor/SbBox.h>
#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <gtest/gtest.h>

#include "nodes/body/CapsuleVolume.h"
#include "nodes/body/CollisionVolumeNode.h"
#include "nodes/body/ExactVolume.h"
#include "support/SceneTestSupport.h"

using namespace figment::test;

namespace {

SbBox3f boundsOf(SoNode* node) {
  SoGetBoundingBoxAction action{SbViewportRegion(100, 100)};
  action.apply(node);
  return action.getBoundingBox();
}

TEST(CollisionVolumeNode, LabelsByTypeAndName) {
  initCoin();
  SceneRoot root = readString("#Inventor V2.1 ascii\nSeparator { DEF Hand ExactVolume { } CapsuleVolume { } }\n");
  ASSERT_TRUE(root);
  EXPECT_EQ(find<ExactVolume>(root.get())->label(), "ExactVolume 'Hand'");
  EXPECT_EQ(find<CapsuleVolume>(root.get())->label(), "CapsuleVolume");
}

TEST(CollisionVolumeNode, TheWireframeIsMadeAgainWhenAFieldChanges) {
  initCoin();
  SceneRoot root = readString("#Inventor V2.1 ascii\nSeparator { CapsuleVolume { } }\n");
  ASSERT_TRUE(root);
  CapsuleVolume* capsule = find<CapsuleVolume>(root.get());
  const SbBox3f before = boundsOf(capsule);
  ASSERT_FALSE(before.isEmpty());
  capsule->oy = 2.0f;  // moved up 2 m: the cached wireframe must not stay where it was
  const SbBox3f after = boundsOf(capsule);
  EXPECT_NEAR(after.getCenter()[1] - before.getCenter()[1], 2.0f, 1e-4f);
}

TEST(CollisionVolumeNode, AnExactVolumeDrawsNothing) {
  initCoin();
  SceneRoot root = readString("#Inventor V2.1 ascii\nSeparator { ExactVolume { part \"head\" } }\n");
  ASSERT_TRUE(root);
  EXPECT_TRUE(boundsOf(root.get()).isEmpty());
}

}  // namespace
