#pragma once
// A garment's rest shape checked against the body it is to drape on, before the first
// step: the mistakes of a garment brought in from a file that make a drape wrong whatever
// the method (issue 29), each of which used to render nonsense without a word. The body's
// own checks, for the tools, are in sim/body/BodyStance.h. All in the scene frame (m, up
// +y, gravity along -y), the body's box and collider in the same frame.
//  - size: a garment many times the body's size is in another unit (a dress in
//    centimetres read as metres is 93 m tall and falls past the body for the whole run);
//  - up: a garment lying on its side (a z-up file read as y-up) wears nothing: its
//    horizontal extent misses the body's vertical axis, and it falls past the feet;
//  - inside: a node that starts inside the body is pushed out at the first step to the
//    nearest surface, which for a waistband inside the hips may be any side;
//  - winding: faces clockwise seen from outside (their normals into the body) drape the
//    same, and the hybrid renderer's ClothingLayer judges the outside from the shape, but
//    what takes a face's front from its winding does not: the export's normals (--export,
//    for Blender or a web viewer) point into the body, a plain face set lights the inside.

#include <optional>

#include "sim/collision/Collider.h"
#include "sim/core/TriangleMesh.h"

namespace figment {

struct GarmentStart {
  // A garment more than this many times the body's largest extent is in another unit (the
  // shipped garments are 0.5 to 0.6 times it, a gown or a cape within 2, a sheet over a
  // small ball a few times; in centimetres they are 50 to 60 times, in inches 20).
  static constexpr double kMaxSizeRatio = 10.0;
  // m: the body's extent when there is no body.
  static constexpr double kTypicalStature = 1.7;
  // The share of the nodes starting inside the body from which the drape may be wrong (a
  // warning). Never an error: the service's size S T-shirt on its largest body starts 74 %
  // inside and drapes whole, the contacts pushing it out.
  static constexpr double kInsideWarningShare = 0.02;
  // m: nodes within this of the body (outside it) tell the winding: the garment's normal
  // there against the body's outward normal.
  static constexpr double kWindingReach = 0.1;
  // The winding is told when at least this share of the garment's area lies within reach,
  // and is clockwise when at least kClockwiseShare of that area faces into the body.
  static constexpr double kWindingAreaShare = 0.25;
  static constexpr double kClockwiseShare = 0.75;

  double extent = 0.0;      // the garment's largest extent, m
  double bodyExtent = 0.0;  // the body's largest extent, m (kTypicalStature without a body)
  double unitFactor = 1.0;  // what to multiply the garment's unit by: 1 unless tooLarge()
  // When the garment (scaled by unitFactor) lies on its side: its direction, in the scene
  // frame, that is up (an axis direction; the body's vertical axis then passes through it).
  std::optional<Vec3> up;
  double insideShare = 0.0;  // of the nodes, those starting inside the body
  // Of the garment's area within kWindingReach of the body, the share whose normals point
  // into it; none when less than kWindingAreaShare of the area lies within reach.
  std::optional<double> inwardShare;

  double sizeRatio() const { return bodyExtent > 0.0 ? extent / bodyExtent : 0.0; }
  bool tooLarge() const { return sizeRatio() > kMaxSizeRatio; }
  bool clockwise() const { return inwardShare && *inwardShare >= kClockwiseShare; }
};

// The checks of `garment` against a body of bounds `bodyBox` (none: no body) whose
// surface `body` answers (null: no body). Inside and winding are measured only on a
// garment of the body's size, standing upright.
GarmentStart checkGarmentStart(const TriangleMesh& garment, const std::optional<Bounds>& bodyBox, const Collider* body);

// True when `vertices` stand round the body of `bodyBox` as worn: the body's vertical axis
// (the vertical line through the box's centre) passes through their horizontal extent, and
// at least half their height lies within the body's.
bool wearsBody(const std::vector<Vec3>& vertices, const Bounds& bodyBox);

}  // namespace figment
