#pragma once
// A flared skirt generated around a body (metres, y up, facing +z): an open cone of cloth
// whose waistband follows the body's natural waist a little outside it, so that, unpinned,
// it slides down onto the hips as it drapes (the large-step integrator's test garment).
// The waist is the narrowest torso section between the hips and the armpits; the
// waistband is that section's convex outline offset outward by `waistClearance`; each
// ring below it lies `flare * t` further out (t = 0 at the waist, 1 at the hem, `length`
// below), and never closer to the body's section there than `waistClearance`. Rest shape and starting placement are the
// same. One open strip, manifold, wound counter-clockwise seen from outside (normals away from the body).

#include "sim/core/TriangleMesh.h"

namespace figment {

struct FlaredSkirtOptions {
  double waistClearance = 0.005;  // m between the waistband and the natural waist
  double length = 0.55;           // m from the waistband down to the hem
  double flare = 0.16;            // m the hem lies further out than the waistband
  int rows = 20;                  // rings of quads, waist to hem
  int columns = 40;               // vertices around each ring
  double clusterGap = 0.04;       // m; see SliceOptions (sim/body/BodySlices.h)
  double torsoHalfWidth = 0.12;   // m; see SliceOptions

  // Throws std::invalid_argument naming the field and value when out of range.
  void validate() const;
};

struct FlaredSkirt {
  TriangleMesh mesh;              // vertices numbered as the triangles first use them
  double waistHeight = 0;         // m, of the natural waist and the waistband
  double waistPerimeter = 0;      // m, of the body's convex waist section
  double waistbandPerimeter = 0;  // m
  double hemHeight = 0;           // m
  double area = 0;                // m^2 of cloth
};

// Generates the skirt around `body`, a closed surface in the scene frame. Deterministic.
// Throws std::invalid_argument for bad options or a body without armpits or a waist.
FlaredSkirt makeFlaredSkirt(const TriangleMesh& body, const FlaredSkirtOptions& options = {});

}  // namespace figment
