#pragma once
// The geometry of a panel's edges (sim/pattern/SewingPattern.h): points along an edge,
// its arc length, and samples evenly spaced by arc length, so both sides of a stitch
// get nodes at the same fractions of their lengths.
//
// Curves: a straight segment; a circular arc of radius r through s and e (centre on the
// perpendicular bisector, the large or small arc, bulging right or left of s -> e);
// quadratic and cubic Béziers with absolute control points.

#include <vector>

#include "sim/pattern/SewingPattern.h"

namespace figment {

// A circle's radius may fall short of half its chord by this fraction (rounding in a file's
// decimals) and is then taken as a half circle; shorter, the arc does not exist and the
// functions below throw std::invalid_argument.
constexpr double kArcRadiusSlack = 1e-6;

// The point at parameter t in [0, 1] along the edge (not arc length: a Bézier's own
// parameter, an arc's angle fraction).
Vec2 edgePoint(const Panel& panel, int edge, double t);

// The edge's arc length (m), to 1e-9 relative.
double edgeLength(const Panel& panel, int edge);

// `segments` + 1 points from the edge's start to its end (both included), spaced evenly
// by arc length. segments >= 1.
std::vector<Vec2> sampleEdge(const Panel& panel, int edge, int segments);

}  // namespace figment
