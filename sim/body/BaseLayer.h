#pragma once
// A plain base layer (underwear) cut from a made body's own skin, as shopping avatars wear
// under whatever is tried on: briefs, and for a women's body a band over the bust. Each
// piece is the skin's triangles inside the piece's bounds, clipped exactly at them (so an
// edge is a clean line, not the skin's triangles' zigzag), and lifted off the skin along
// its normals by `offset`.
//
// The offset is less than the cloth's clearance (sim/cloth/ClothParameters.h, 3 mm): a
// garment comes to rest outside the layer without draping on it, so the drape of a size is
// the same with or without it. The fit is measured to the skin, as the size chart's girths
// are: ISO 8559-1 measures a body in its underwear.

#include <vector>

#include "sim/body/BodyMeasurements.h"
#include "sim/core/TriangleMesh.h"

namespace figment {

struct BaseLayerShape {
  bool top = true;         // the band over the bust; false: briefs only (a men's body)
  double offset = 0.0015;  // m off the skin
};

// Where the pieces end, from the rest body's landmarks (heights, m) and the hips' half
// width: the briefs from the crotch up to a third of the way from hip to waist level, the
// leg openings rising from the crotch to hip level at the sides; the band from 2 cm below
// the underbust to halfway from bust to armpit.
struct BaseLayerBounds {
  double centreX = 0;                  // the body's middle (x)
  double briefsTop = 0;                // y
  double legBottom = 0;                // y of the leg openings at the middle (just under the crotch)
  double legSlope = 0;                 // rise of the leg openings per metre out from the middle
  double bandBottom = 0, bandTop = 0;  // y; equal when there is no band
};
BaseLayerBounds baseLayerBounds(const TriangleMesh& rest, const std::vector<int>& triangleParts,
                                const BodyLandmarks& landmarks, const BaseLayerShape& shape);

// The layer over `posed`, decided on `rest` (the same body in its rest pose, vertices and
// triangles numbered as posed's): the trunk's and thighs' triangles (skinTriangleParts'
// parts 0, 8, 9) for the briefs, the trunk's for the band, clipped to `bounds`, their
// vertices moved `shape.offset` out along posed's vertex normals. One welded surface: a
// point where a piece's edge crosses a skin edge is shared by the two triangles beside it.
// Throws std::invalid_argument when the meshes or the parts disagree in size.
TriangleMesh cutBaseLayer(const TriangleMesh& rest, const TriangleMesh& posed, const std::vector<int>& triangleParts,
                          const BaseLayerBounds& bounds, const BaseLayerShape& shape);

}  // namespace figment
