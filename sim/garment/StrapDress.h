#pragma once
// The default garment: a strap dress generated around a body (metres, y up, facing +z),
// roughly placed but outside the body everywhere by a clearance, for the simulation to
// drape. A tube (bodice and skirt) from just under the armpits to about the knees, its top
// edge raised between the straps in front and at the back (a straight-across neckline over
// the bust), and two shoulder straps from the tube's front top edge over each shoulder to its
// back top edge.
// One connected mesh, manifold with a boundary, wound counter-clockwise seen from outside
// (normals away from the body). Method and sources at the top of StrapDress.cpp.

#include <optional>

#include "sim/core/TriangleMesh.h"

namespace figment {

struct StrapDressOptions {
  double clearance = 0.01;          // m kept between every cloth vertex and the body
  std::optional<double> topHeight;  // m, the top edge under the arms; default: armpits - topBelowArmpit
  double topBelowArmpit = 0.03;     // m
  double necklineRise = 0.08;       // m the top edge rises between the straps' centre lines, front and back
  double necklineFade = 0.04;       // m in |x| beyond the straps' centre lines over which the rise fades out
  std::optional<double> hemHeight;  // m; default: body bottom + hemHeightRatio * stature
  double hemHeightRatio = 0.30;     // knee height is ~0.285 of stature (Drillis & Contini 1966)
  int rows = 18;                    // rows of quads in the tube, top to hem
  int columns = 40;                 // vertices around the tube
  double hemFlare = 0.04;           // m added to the radius from the hips down to the hem (A-line)
  double strapOffset = 0.10;        // m, |x| of each strap's centre line from the torso's centre
  double strapWidth = 0.03;         // m; two quads across
  int strapSegments = 14;           // quads along each strap, front to back
  double clusterGap = 0.04;         // m; see SliceOptions
  double torsoHalfWidth = 0.12;     // m; see SliceOptions

  // Throws std::invalid_argument naming the field and value when out of range.
  void validate() const;
};

struct StrapDress {
  TriangleMesh mesh;          // vertices numbered in the order the triangles first use them
  int tubeTriangles = 0;      // the mesh's first triangles are the tube's (2 x columns x rows), the straps' follow
  double topHeight = 0;       // m, the tube's top edge under the arms
  double necklineHeight = 0;  // m, the top edge between the straps: topHeight + necklineRise
  double hemHeight = 0;       // m, the tube's bottom edge
  double armpitHeight = 0;    // m, as measured on the body
  double neckHeight = 0;      // m, as measured on the body
  double neckCentreX = 0;     // m, the middle of the torso-band section at neckHeight
  double neckHalfWidth = 0;   // m, half that section's width in x (0 when the section is empty)
  double strapX[2] = {0, 0};  // m, x of the left and right straps' centre lines
};

// Generates the dress around `body`, a closed surface in the scene frame. Deterministic.
// Throws std::invalid_argument for bad options or a body it cannot fit (no armpits found,
// a cross section that does not surround the dress's axis).
StrapDress makeStrapDress(const TriangleMesh& body, const StrapDressOptions& options = {});

}  // namespace figment
