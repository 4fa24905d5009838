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
// lies in front of a ClothingLayer: their screen rectangles overlap and the separator's
// bounding box ends nearer to the eye than the layer's centre (the part is outside the
// garment, between it and the eye: a forearm across a shirt, not a torso inside it).
// Every ClothingLayer that such a separator lies in front of is masked; all others are
// set FALSE. Call it whenever the camera moves (figment-view does before each render).
StencilSettings applyStencilRule(SoNode* root, const SbViewportRegion& viewport, const SbViewVolume& view);

}  // namespace figment
