#pragma once
// The rule that sets StencilSeparator.writeStencil and ClothingLayer.masked for a view
// (paper §5 leaves it open: "the boolean fields are set" when the viewpoint changes).

#include <Inventor/SbViewVolume.h>
#include <Inventor/SbViewportRegion.h>

class SoNode;

namespace figment {

struct StencilSettings {
  int writers = 0;  // StencilSeparators set to write the stencil
  int masked = 0;   // ClothingLayers set to be masked
};

// For the camera `view`, every StencilSeparator under `root` writes the stencil when it
// lies in front of a ClothingLayer: their screen rectangles overlap, and the centre of
// the separator's bounding box lies in the front half of the layer's depth range along
// the viewing direction (nearer than halfway from the layer's centre to its nearest
// point): a forearm across a shirt, the near arm seen from the side; not a torso the
// garment encloses, nor a part behind the garment.
// Every ClothingLayer that such a separator lies in front of is masked; all others are
// set FALSE. Call it whenever the camera moves (figment-view does before each render).
StencilSettings applyStencilRule(SoNode* root, const SbViewportRegion& viewport, const SbViewVolume& view);

}  // namespace figment
