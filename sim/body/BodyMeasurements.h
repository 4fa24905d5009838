#pragma once
// A body's measurements as a tape measures them (ISO 8559-1 names), from landmarks found
// on its mesh. What a body is made to (sim/body/MeasuredBody.h) and what
// figment-measure prints. Definitions, and where each departs from the standard, in
// docs/bodies.md; the landmark rules at the top of BodyMeasurements.cpp.

#include <string>
#include <utility>
#include <vector>

#include "sim/core/TriangleMesh.h"

namespace figment {

// Heights (m above the floor, the body's lowest point) of the levels the girths are taken at.
struct BodyLandmarks {
  double crotch = 0, hip = 0, waist = 0, underbust = 0, bust = 0, armpit = 0, shoulder = 0, neck = 0;
};

// All lengths in metres. A girth is the perimeter of the convex hull of the body's section
// at its level: a tape bridges hollows (the cleavage, the gap between the legs, the navel).
struct BodyMeasurements {
  double stature = 0;         // floor to the top of the head
  double bustGirth = 0;       // horizontal, the fullest level of the chest below the armpits
  double underbustGirth = 0;  // horizontal, just below the breasts (the fold)
  double waistGirth = 0;      // horizontal, the narrowest level between hips and bust
  double hipGirth = 0;        // horizontal, the fullest level between crotch and waist
  double neckGirth = 0;       // horizontal, the narrowest level of the neck
  double shoulderWidth = 0;   // across the shoulders' outer contour, midway from armpits to neck
  double upperArmGirth = 0;   // perpendicular to the upper arm, at the armpit
  double thighGirth = 0;      // horizontal, the fuller thigh 2 cm below the crotch
  double insideLeg = 0;       // floor to the crotch
  double armLength = 0;       // shoulder point along the arm's axis to the wrist
  BodyLandmarks landmarks;

  // (JSON key, value) in the order above: stature, bust_girth, underbust_girth, ...
  std::vector<std::pair<std::string, double>> named() const;
  // The value under `key` (one of named()'s); throws std::invalid_argument for another.
  double byName(const std::string& key) const;
};

// Measures a standing body: metres, y up, arms away from the torso (A- or T-pose), legs
// apart, about symmetric about x = the middle of its bounds. Throws std::invalid_argument
// ("body: no crotch found ...") when a landmark cannot be found.
BodyMeasurements measureBody(const TriangleMesh& body);
// The measurements `keys` (named() keys) name and the landmarks they need, each the same
// as measureBody(body) gives it; the others 0 (or as measureBody gives them). What a fit measures at each step:
// a fit to four girths need not follow the arms (a third of a full measurement's time).
// Throws as measureBody, and std::invalid_argument for an unknown key.
BodyMeasurements measureBody(const TriangleMesh& body, const std::vector<std::string>& keys);

// The perimeter (m) of the convex hull of `points`, each taken in the plane with unit
// normal `normal`: what a taut tape laid round them in that plane measures.
double convexPerimeter(const std::vector<Vec3>& points, const Vec3& normal);

}  // namespace figment
