#include "nodes/StencilRule.h"

#include "nodes/ClothingLayer.h"
#include "nodes/StencilSeparator.h"

#include <Inventor/SbBox2f.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/lists/SoPathList.h>

#include <algorithm>
#include <limits>
#include <vector>

namespace figment {

namespace {

// Where a node lies for the camera: its screen rectangle and its depth range along the
// viewing direction (nearest corner and centre) from its world bounding box.
struct Extent {
  SbBox2f screen;
  float nearest = std::numeric_limits<float>::max();
  float centre = 0.0f;
  bool empty = true;
};

Extent extentOf(SoPath* path, const SbViewportRegion& viewport, const SbViewVolume& view) {
  SoGetBoundingBoxAction bounds(viewport);
  bounds.apply(path);
  const SbBox3f box = bounds.getBoundingBox();  // world frame
  Extent extent;
  if (box.isEmpty()) return extent;
  extent.empty = false;
  const SbVec3f eye = view.getProjectionPoint(), direction = view.getProjectionDirection();
  const SbVec3f& low = box.getMin();
  const SbVec3f& high = box.getMax();
  for (int corner = 0; corner < 8; ++corner) {
    const SbVec3f p(corner & 1 ? high[0] : low[0], corner & 2 ? high[1] : low[1], corner & 4 ? high[2] : low[2]);
    const float depth = (p - eye).dot(direction);
    extent.nearest = std::min(extent.nearest, depth);
    SbVec3f screen;
    view.projectToScreen(p, screen);
    extent.screen.extendBy(SbVec2f(screen[0], screen[1]));
  }
  extent.centre = (box.getCenter() - eye).dot(direction);
  return extent;
}

std::vector<SoPath*> pathsTo(SoNode* root, SoType type) {
  SoSearchAction search;
  search.setType(type);
  search.setInterest(SoSearchAction::ALL);
  search.setSearchingAll(TRUE);  // also inside switches that are off at the moment
  search.apply(root);
  const SoPathList& found = search.getPaths();
  std::vector<SoPath*> paths;
  for (int i = 0; i < found.getLength(); ++i) {
    found[i]->ref();
    paths.push_back(found[i]);
  }
  return paths;
}

}  // namespace

StencilSettings applyStencilRule(SoNode* root, const SbViewportRegion& viewport, const SbViewVolume& view) {
  StencilSettings settings;
  const std::vector<SoPath*> parts = pathsTo(root, StencilSeparator::getClassTypeId());
  const std::vector<SoPath*> layers = pathsTo(root, ClothingLayer::getClassTypeId());
  std::vector<Extent> layerExtents;
  for (SoPath* layer : layers) layerExtents.push_back(extentOf(layer, viewport, view));
  std::vector<bool> masked(layers.size(), false);
  for (SoPath* part : parts) {
    const Extent p = extentOf(part, viewport, view);
    bool writes = false;
    for (size_t l = 0; l < layers.size(); ++l) {
      const Extent& garment = layerExtents[l];
      if (p.empty || garment.empty || !p.screen.intersect(garment.screen)) continue;
      // In front: the part's centre lies in the front half of the garment's depth,
      // nearer than halfway from the garment's centre to its nearest point. A part the
      // garment encloses (a torso) sits about its centre; one outside and nearer (a
      // forearm across a shirt, the near arm from the side) is well in front of it.
      if (p.centre < garment.centre - 0.5f * (garment.centre - garment.nearest)) writes = true, masked[l] = true;
    }
    auto* separator = static_cast<StencilSeparator*>(part->getTail());
    if (separator->writeStencil.getValue() != writes) separator->writeStencil.setValue(writes);
    settings.writers += writes;
  }
  for (size_t l = 0; l < layers.size(); ++l) {
    auto* layer = static_cast<ClothingLayer*>(layers[l]->getTail());
    if (layer->masked.getValue() != masked[l]) layer->masked.setValue(masked[l]);
    settings.masked += masked[l];
  }
  for (SoPath* path : parts) path->unref();
  for (SoPath* path : layers) path->unref();
  return settings;
}

}  // namespace figment
