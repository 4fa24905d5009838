#pragma once
// Where a pattern's panels go around a body that is not the one the pattern was made for.
// GarmentCode places panels around its own body: feet at y = 0, its axis along y through
// x = z = 0, facing +z. On another body (FIGMENT's are MakeHuman's, or any mesh in the scene
// frame) the panels are moved so that the pattern's feet, waist and axis meet that body's:
// heights map piecewise linearly from the pattern's body to this one, feet to feet, waist to
// waist, head to head (a skirt's waistband stays at the waist of a shorter body, or of one
// whose waist sits higher: MakeHuman's women's is 4 cm above GarmentCode's at the same
// stature), each panel moved by what that does to its centre; the axis moves to the centre
// of the body's torso at its waist, and the panels placed along the arms (sleeves, cuffs: turned about z by the
// pattern's arm angle) turn about their armhole to the body's own arm angle (GarmentCode's bodies hold their arms 45
// degrees below the horizontal, MakeHuman's about 53). The panels themselves keep their shapes: a garment is the same
// garment on any body.

#include "sim/core/TriangleMesh.h"
#include "sim/pattern/SewingPattern.h"

namespace figment {

// GarmentCode's mean bodies have their waist (height - head_l - waist_line) at this share of
// their stature: 106.05 cm of 168 (women's 38), 110.2 of 174 (men's 48); the patterns'
// bodies scale their lengths with stature (scenes/patterns/bodies/).
constexpr double kGarmentCodeWaistShare = 0.632;

struct PatternPlacement {
  double feet = 0.0;         // m: the body's lowest point (y)
  double heightScale = 1.0;  // the body's stature over the pattern's body's
  // m above the feet: the body's waist and the pattern's body's (0: not known; heights then
  // scale by heightScale alone), and the pattern's body's stature.
  double waist = 0.0, patternWaist = 0.0, patternStature = 0.0;
  Vec2 axis = Vec2::Zero();  // m: (x, z) of the body's torso centre
  double armAngle = 0.0;     // degrees below the horizontal of the body's arms; 0: not known
  // Where a point placed for the pattern's own body goes on this body: (x, y, z) ->
  // (x + axis.x, feet + height(y), z + axis.z).
  Vec3 operator()(const Vec3& p) const { return {p.x() + axis.x(), feet + height(p.y()), p.z() + axis.y()}; }
  // A height above the pattern's body's feet, on this body (m above its feet).
  double height(double y) const;
};

// The placement on `body` (metres, y up, facing +z) of a pattern made for a body of
// `madeForStature` (m; 0: the same stature as `body`). The torso's centre is its section's
// at 60 % of the stature (about the waist); the waist is the body's measured one
// (sim/body/BodyMeasurements.h), when it can be measured. Throws std::invalid_argument for an empty body
// or a stature out of [kMinStature, kMaxStature] (sim/body/BodyStance.h).
PatternPlacement placementOn(const TriangleMesh& body, double madeForStature);

// The body's arms' angle below the horizontal, degrees (the left arm's outer contour, +x,
// between 62 % and 78 % of the stature, fitted by a line); 0 when no arm stands apart there.
double armAngleOf(const TriangleMesh& body);

// The pattern with each panel moved as the placement moves its centre, and its arm panels
// turned to the body's arm angle (when the placement knows it).
SewingPattern placed(const SewingPattern& pattern, const PatternPlacement& placement);

}  // namespace figment
