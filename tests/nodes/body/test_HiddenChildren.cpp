// A hidden mesh: a separator of its own holding empty coordinates and a face set, reached by
// an action through the child list as any shape is.
#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/misc/SoChildList.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoShape.h>
#include <gtest/gtest.h>

#include "nodes/body/HiddenChildren.h"
#include "support/SceneTestSupport.h"

namespace {

TEST(HiddenChildren, AppendsASeparatorWithEmptyCoordinatesAndFaces) {
  figment::test::initCoin();
  auto* owner = new SoSeparator;  // a node to own the list, as the drawing nodes do
  owner->ref();
  auto* children = new SoChildList(owner);  // gone before its owner
  const figment::HiddenMesh mesh = figment::appendHiddenMesh(*children);
  ASSERT_EQ(children->getLength(), 1);
  auto* root = static_cast<SoSeparator*>((*children)[0]);
  ASSERT_TRUE(root->isOfType(SoSeparator::getClassTypeId()));
  ASSERT_EQ(root->getNumChildren(), 2);
  EXPECT_EQ(root->getChild(0), mesh.coordinates);
  EXPECT_EQ(root->getChild(1), mesh.faces);
  EXPECT_EQ(mesh.coordinates->point.getNum(), 0);

  // Filled, it is what an action traversing the hidden children meets.
  const SbVec3f points[] = {{0, 0, 0}, {2, 0, 0}, {0, 1, 0}};
  mesh.coordinates->point.setValues(0, 3, points);
  const int32_t triangle[] = {0, 1, 2, -1};
  mesh.faces->coordIndex.setValues(0, 4, triangle);
  // A callback traversal of the owner reaching its hidden children the way a drawing node
  // does (from inside its own traversal) meets the triangle; without that, nothing.
  struct Visit {
    SoNode* owner;
    SoChildList* children;
    bool hidden;
    int triangles = 0;
  };
  for (bool hidden : {false, true}) {
    Visit visit{owner, children, hidden};
    SoCallbackAction action;
    action.addPreCallback(
        SoSeparator::getClassTypeId(),
        [](void* data, SoCallbackAction* a, const SoNode* node) {
          auto* v = static_cast<Visit*>(data);
          if (node == v->owner && v->hidden) figment::traverseHidden(*v->children, a);
          return SoCallbackAction::CONTINUE;
        },
        &visit);
    action.addTriangleCallback(
        SoShape::getClassTypeId(),
        [](void* data, SoCallbackAction*, const SoPrimitiveVertex*, const SoPrimitiveVertex*,
           const SoPrimitiveVertex*) { ++static_cast<Visit*>(data)->triangles; },
        &visit);
    action.apply(owner);
    EXPECT_EQ(visit.triangles, hidden ? 1 : 0) << hidden;
  }
  delete children;
  owner->unref();
}

}  // namespace
