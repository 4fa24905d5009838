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
// The landmark is where the garment's seams cross the top of the body: for every stitch
// between two panels (a dart, within one panel, moves with its panel), the midpoints of
// its node pairs, where the seam closes. One that lies under the body's top surface (the
// line straight up from it crosses the surface once: a shoulder, the top of the trapezius)
// says how far the garment must rise for that seam to close on the surface. The garment
// rises by the largest such depth. A garment whose seams all close outside the body
// (skirts, trousers: nothing or an even number of crossings above) or inside it under
// more of it (a side seam in a waist, under the chest and shoulders: three) does not move.

#include <vector>

#include "sim/core/TriangleMesh.h"
#include "sim/pattern/SewingPattern.h"

namespace figment {

struct ShoulderRestOptions {
  // m: seam points deeper than this under the body's top are not under its shoulders but
  // through the body (a sleeve's seam in the torso, under a shoulder 20 cm above): they say
  // nothing of where the garment rests.
  double reach = 0.12;
  double clearance = 0.005;  // m: above the surface, where the seam closes
  int samples = 8;           // points per stitched edge (segments)
};

// How far (m, >= 0) the placed pattern must rise for every stitch that closes under the
// body's top surface to close on it instead; 0 when none does. `pattern` is placed in the
// body's frame (PatternPlacement.h's placed()); `body` a closed surface, y up.
double shoulderRise(const SewingPattern& pattern, const TriangleMesh& body, const ShoulderRestOptions& options = {});

// The heights (m) at which the vertical line through (x, z) crosses the body's surface
// above `from`, lowest first.
std::vector<double> crossingsAbove(const TriangleMesh& body, double x, double z, double from);

}  // namespace figment
