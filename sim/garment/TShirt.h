#pragma once
// A T-shirt with short sleeves generated around a body in its rest pose (metres, y up,
// facing +z): the body's own skin over the torso and the upper arms, stood off it by
// `ease` along the skin's normals, its openings cut along smooth surfaces, then resampled
// (sim/progressive/Resampling.h: decimated, or subdivided and decimated) to the chosen
// number of sections, the openings kept finer and smoothed along their surfaces. The skin
// is cut into parts by the estimated skeleton (sim/body/BodyParts.h): the shirt keeps the
// upper and lower torso, the hips above the hem (and the thighs' tops above it), the neck
// and the upper arms, then cuts the hem along its level plane, each sleeve's end square to
// its upper arm at `sleeveShare` of the way to the elbow, and the neckline along a sphere
// round the neck `necklineDrop` below its base (neck hole, sleeve ends, hem).
// One piece, manifold, wound counter-clockwise seen from outside; rest shape and
// starting placement are the same.

#include "sim/core/TriangleMesh.h"

namespace figment {

struct TShirtOptions {
  double ease = 0.015;           // m the shirt stands off the skin
  double hemAboveCrotch = 0.12;  // m: the hem's height above the crotch
  double sleeveShare = 0.55;     // of the upper arm, shoulder to elbow, inside the sleeve
  double necklineDrop = 0.03;    // m the neckline lies below the neck's base
  int triangles = 1000;          // sections of the shirt

  // Throws std::invalid_argument naming the field and value when out of range.
  void validate() const;
};

struct TShirt {
  TriangleMesh mesh;      // vertices numbered as the triangles first use them
  double hemHeight = 0;   // m
  double area = 0;        // m^2 of cloth
  int skinTriangles = 0;  // of the body's skin it was made from, after the hem's cut
};

// Generates the shirt around `body`, a closed surface in the scene frame. Deterministic.
// Throws std::invalid_argument for bad options or a body whose skeleton cannot be
// estimated.
TShirt makeTShirt(const TriangleMesh& body, const TShirtOptions& options = {});

}  // namespace figment
