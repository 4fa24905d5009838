#include "nodes/render/DepthSortedGroup.h"

#include <Inventor/SbViewVolume.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/elements/SoCacheElement.h>
#include <Inventor/elements/SoModelMatrixElement.h>
#include <Inventor/elements/SoViewVolumeElement.h>
#include <Inventor/elements/SoViewportRegionElement.h>
#include <Inventor/misc/SoChildList.h>
#include <Inventor/misc/SoState.h>

#include <algorithm>
#include <numeric>
#include <vector>

#include "nodes/NodeSource.h"

FIGMENT_NODE_SOURCE(DepthSortedGroup, SoGroup, "Group")

DepthSortedGroup::DepthSortedGroup() {
  SO_NODE_CONSTRUCTOR(DepthSortedGroup);
}

DepthSortedGroup::~DepthSortedGroup() = default;

void DepthSortedGroup::GLRender(SoGLRenderAction* action) {
  int pathIndexCount;
  const int* pathIndices;
  // Along a path (render a path to one child), keep the path's own order.
  if (action->getPathCode(pathIndexCount, pathIndices) == SoAction::IN_PATH) {
    inherited::GLRender(action);
    return;
  }
  SoState* state = action->getState();
  SoCacheElement::invalidate(state);  // the order depends on the view
  const SbViewVolume& view = SoViewVolumeElement::get(state);
  const SbMatrix& toWorld = SoModelMatrixElement::get(state);
  const bool perspective = view.getProjectionType() == SbViewVolume::PERSPECTIVE;
  const SbVec3f eye = view.getProjectionPoint();
  const SbVec3f direction = view.getProjectionDirection();

  SoChildList* pieces = getChildren();
  const int count = pieces->getLength();
  SoGetBoundingBoxAction bounds(SoViewportRegionElement::get(state));
  std::vector<float> distance(count, 0.0f);
  for (int i = 0; i < count; ++i) {
    bounds.apply((*pieces)[i]);
    const SbBox3f box = bounds.getBoundingBox();  // in this group's frame
    if (box.isEmpty()) continue;
    SbVec3f centre;
    toWorld.multVecMatrix(box.getCenter(), centre);
    distance[i] = perspective ? (centre - eye).length() : (centre - eye).dot(direction);
  }
  std::vector<int> order(count);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return distance[a] > distance[b]; });
  for (int i : order) {
    pieces->traverse(action, i);
    if (action->hasTerminated()) break;
  }
}
