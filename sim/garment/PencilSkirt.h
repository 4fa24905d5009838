#pragma once
// A straight (pencil) skirt generated around a body (metres, y up, facing +z): a fitted
// tube from the natural waist to about the knee, `waistEase` (m of girth) over the body at
// the waist and `hipEase` at the hips, falling straight below the hips' widest part and
// narrowing by `taper` (m of girth) to the hem. The style where fit decides: a size too
// small stretches over the hips, a size too large hangs off them. One open strip,
// manifold, wound counter-clockwise seen from outside; rest shape and starting placement
// are the same. Method at the top of PencilSkirt.cpp.

#include "sim/core/TriangleMesh.h"

namespace figment {

struct PencilSkirtOptions {
  double waistEase = 0.02;       // m of girth over the body's convex waist section
  double hipEase = 0.04;         // m of girth over the body's convex hip section
  double length = 0.55;          // m from the waistband down to the hem
  double taper = 0.04;           // m of girth the hem lies inside the straight fall below the hips
  int rows = 22;                 // rings of quads, waist to hem
  int columns = 48;              // vertices around each ring
  double clusterGap = 0.04;      // m; see SliceOptions (sim/body/BodySlices.h)
  double torsoHalfWidth = 0.12;  // m; see SliceOptions

  // Throws std::invalid_argument naming the field and value when out of range.
  void validate() const;
};

struct PencilSkirt {
  TriangleMesh mesh;       // vertices numbered ring by ring, waist first
  double waistHeight = 0;  // m, of the natural waist and the waistband
  double hipHeight = 0;    // m, of the hips' widest section
  double hemHeight = 0;    // m
};

// Generates the skirt around `body`, a closed surface in the scene frame. Deterministic.
// Throws std::invalid_argument for bad options or a body without a waist or hips.
PencilSkirt makePencilSkirt(const TriangleMesh& body, const PencilSkirtOptions& options = {});

}  // namespace figment
