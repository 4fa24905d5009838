#pragma once
// Where a pattern's panels go around a body that is not the one the pattern was made for.
// GarmentCode places panels around its own body: feet at y = 0, its axis along y through
// x = z = 0, facing +z. On another body (FIGMENT's are MakeHuman's, or any mesh in the scene
// frame) the panels are moved so that the pattern's feet and axis meet that body's: heights
// scale with the ratio of the two statures (a skirt's waistband stays at the waist of a
// shorter body), the axis moves to the centre of the body's torso at its waist, and the
// panels placed along the arms (sleeves, cuffs: turned about z by the pattern's arm angle)
// turn about their armhole to the body's own arm angle (GarmentCode's bodies hold their
// arms 45 degrees below the horizontal, MakeHuman's about 53). A garment whose seams would
// close under the body's shoulders then rises until they close on them
// (sim/pattern/ShoulderRest.h), and the panels along the arms move clear of them
// (sim/pattern/LimbClearance.h). The panels themselves keep their shapes: a garment is the
// same garment on any body.

#include <memory>

#include "sim/core/TriangleMesh.h"
#include "sim/pattern/SewingPattern.h"

namespace figment {

struct PatternPlacement {
  double feet = 0.0;         // m: the body's lowest point (y)
  double heightScale = 1.0;  // the body's stature over the pattern's body's
  Vec2 axis = Vec2::Zero();  // m: (x, z) of the body's torso centre
  double armAngle = 0.0;     // degrees below the horizontal of the body's arms; 0: not known
  // The body's surface, to rest a garment's shoulders on (ShoulderRest.h) and to move
  // sleeves clear of (LimbClearance.h); null: not known, the garment neither rises nor
  // moves its sleeves.
  std::shared_ptr<const TriangleMesh> surface;
  // Where a point placed for the pattern's own body goes on this body: (x, y, z) ->
  // (x + axis.x, feet + heightScale y, z + axis.z).
  Vec3 operator()(const Vec3& p) const { return {p.x() + axis.x(), feet + heightScale * p.y(), p.z() + axis.y()}; }
};

// The placement on `body` (metres, y up, facing +z) of a pattern made for a body of
// `madeForStature` (m; 0: the same stature as `body`). The torso's centre is its section's
// at 60 % of the stature (about the waist). Throws std::invalid_argument for an empty body
// or a stature out of [kMinStature, kMaxStature] (sim/body/BodyStance.h).
PatternPlacement placementOn(const TriangleMesh& body, double madeForStature);

// The body's arms' angle below the horizontal, degrees (the left arm's outer contour, +x,
// between 62 % and 78 % of the stature, fitted by a line); 0 when no arm stands apart there.
double armAngleOf(const TriangleMesh& body);

// The pattern with each panel's translation moved by the placement, its arm panels turned
// to the body's arm angle (when the placement knows it), and, when the placement knows the
// body's surface, all of it risen by shoulderRise() and its arm panels moved clear of the
// arms (moveClearOf()).
SewingPattern placed(const SewingPattern& pattern, const PatternPlacement& placement);

}  // namespace figment
