#include "nodes/render/StencilRule.h"

#include "nodes/render/ClothingLayer.h"
#include "nodes/SceneSearch.h"
#include "nodes/render/StencilSeparator.h"

#include <Inventor/SbBox2f.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>

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

}  // namespace

StencilSettings applyStencilRule(SoNode* root, const SbViewportRegion& viewport, const SbViewVolume& view) {
  StencilSettings settings;
  const SoPathList parts = findAll(root, StencilSeparator::getClassTypeId());
  const SoPathList layers = findAll(root, ClothingLayer::getClassTypeId());
  std::vector<Extent> layerExtents;
  for (int l = 0; l < layers.getLength(); ++l) layerExtents.push_back(extentOf(layers[l], viewport, view));
  std::vector<bool> masked(layers.getLength(), false);
  for (int i = 0; i < parts.getLength(); ++i) {
    SoPath* part = parts[i];
    const Extent p = extentOf(part, viewport, view);
    bool writes = false;
    for (size_t l = 0; l < layerExtents.size(); ++l) {
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
  for (int l = 0; l < layers.getLength(); ++l) {
    auto* layer = static_cast<ClothingLayer*>(layers[l]->getTail());
    if (layer->masked.getValue() != masked[l]) layer->masked.setValue(masked[l]);
    settings.masked += masked[l];
  }
  return settings;
}

}  // namespace figment
