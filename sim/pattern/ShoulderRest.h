#pragma once
// Where a garment that hangs from the shoulders rests on a body it was not made for.
//
// A pattern's panels are placed for the body it was made for; on another body of the same
// stature the shoulders may stand higher (MakeHuman's men's stand 4 to 6 cm higher than
// GarmentCode's, its women's 2 to 5 cm: docs/patterns.md, "Two bodies"). Sewing pulls each
// seam's pairs straight together, so a shoulder seam whose front and back halves start
// below the body's shoulder closes inside it: the body pushes the cloth out of the way it
// can, down the chest and back, and the garment ends up pulled down off the shoulders
// (a fitted shirt torn across the chest, its sleeves beside the arms).
//
// The landmark is where the garment's seams cross over the top of the body: for every
// stitch between two panels (a dart, within one panel, moves with its panel), the
// midpoints of its node pairs, where the seam closes. A pair whose two nodes start outside
// the body but whose midpoint lies under the body's top surface (the line straight up from
// it crosses the surface once, within reach, where the surface faces up: a shoulder, the
// top of the trapezius) says how far the garment must rise for that seam to close on the
// surface. The garment rises by the largest such depth. Nothing else moves it: a seam that
// closes outside the body (skirts, trousers), one under more of the body (a tight waist's
// side seam, under the chest: three crossings), one whose panel already lies in the body
// (a waistband on a belly that stands out past it: its nodes inside), or one under a
// surface that slopes off (a wide side seam across a hanging arm, whose top faces 65
// degrees off the vertical there).

#include <vector>

#include "sim/core/TriangleMesh.h"
#include "sim/pattern/SewingPattern.h"

namespace figment {

struct ShoulderRestOptions {
  // m: seam points deeper than this under the body's top are not under its shoulders but
  // through the body (a sleeve's seam in the torso, under a shoulder 20 cm above): they say
  // nothing of where the garment rests.
  double reach = 0.12;
  // The surface above must face up: its normal's y above this (0.5: within 60 degrees of
  // the vertical). Measured on the chart bodies where the shipped tops' shoulder seams
  // close (at a shoulder's front, 6 cm before its middle): 0.6 to 0.86; where a wide
  // T-shirt's side seam crosses a hanging arm: 0.39.
  double upward = 0.5;
  double clearance = 0.005;  // m: above the surface, where the seam closes
  int samples = 8;           // points per stitched edge (segments)
};

// How far (m, >= 0) the placed pattern must rise for every stitch that closes under the
// body's top surface to close on it instead; 0 when none does. `pattern` is placed in the
// body's frame (PatternPlacement.h's placed()); `body` a closed surface, y up.
double shoulderRise(const SewingPattern& pattern, const TriangleMesh& body, const ShoulderRestOptions& options = {});

// Where the vertical line through (x, z) crosses the body's surface above `from`, lowest
// first: the height (m) and the y of the crossed triangle's unit normal (the body's
// triangles counter-clockwise seen from outside: > 0 where the line leaves the body up).
struct Crossing {
  double y = 0.0;
  double up = 0.0;
};
std::vector<Crossing> crossingsAbove(const TriangleMesh& body, double x, double z, double from);

// Whether `p` lies inside the closed surface `body` (an odd number of crossings above it).
bool inside(const TriangleMesh& body, const Vec3& p);

}  // namespace figment
