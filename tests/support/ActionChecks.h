#pragma once
// Coin's non-rendering actions applied as a viewer applies them (a 100 x 100 viewport):
// for node tests that check a node behaves like the plain node it stands in for.

#include <Inventor/SbBox3f.h>
#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoPickedPoint.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/actions/SoGetPrimitiveCountAction.h>
#include <Inventor/actions/SoRayPickAction.h>
#include <Inventor/nodes/SoNode.h>

namespace figment::test {

inline const SbViewportRegion kActionViewport(100, 100);

inline SbBox3f boundingBoxOf(SoNode* root) {
  SoGetBoundingBoxAction box(kActionViewport);
  box.apply(root);
  return box.getBoundingBox();
}

inline int triangleCountOf(SoNode* root) {
  SoGetPrimitiveCountAction count;
  count.apply(root);
  return count.getTriangleCount();
}

// The nearest point hit by a ray from `from` along -z; owned by `pick`, null for none.
inline const SoPickedPoint* pickAlongMinusZ(SoRayPickAction& pick, SoNode* root, const SbVec3f& from) {
  pick.setRay(from, SbVec3f(0.0f, 0.0f, -1.0f));
  pick.apply(root);
  return pick.getPickedPoint();
}

}  // namespace figment::test
