#pragma once
// A sewing pattern as plain data: flat panels, each with its outline of edges (straight,
// circular arcs, quadratic or cubic Bézier curves) and its placement around a standing
// body, and the stitches that say which edge is sewn to which. Units are metres; the
// body frame is y up, feet at y = 0, the body facing +z (GarmentCode's frame).
//
// The data of any pattern format: io/PatternFile reads GarmentCode's specification JSON
// into it (control points turned into absolute panel coordinates, centimetres into
// metres, Euler angles into a matrix), so nothing in sim/ knows a file format.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "sim/core/TriangleMesh.h"

namespace figment {

using Vec2 = Eigen::Vector2d;

// The shape of an edge between its two end points s and e (panel coordinates, m).
struct EdgeCurve {
  enum class Kind { Straight, Circle, Quadratic, Cubic };
  Kind kind = Kind::Straight;
  // Circle: an arc of this radius (m) from s to e; the large or the small one of the two;
  // bulging to the right of s -> e (seen with the panel's v axis up) when `right`.
  double radius = 0.0;
  bool largeArc = false;
  bool right = false;
  // Quadratic: one control point; Cubic: two (panel coordinates, m, absolute).
  std::vector<Vec2> controls;
};

struct PanelEdge {
  int from = 0, to = 0;  // indices into the panel's vertices
  EdgeCurve curve;
};

struct Panel {
  std::string name;
  std::vector<Vec2> vertices;    // m, in the panel's plane
  std::vector<PanelEdge> edges;  // one closed loop: edges[k].to == edges[k + 1].from
  // Placement around the body: a panel point (u, v) lands at rotation (u, v, 0) +
  // translation (m).
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Vec3 translation = Vec3::Zero();
};

// One edge of one panel, by index.
struct EdgeRef {
  int panel = 0, edge = 0;
};

// Two edges sewn together, paired by fraction of arc length: by default the second runs
// the opposite way to the first (the usual seam, both panels' right sides out);
// `sameDirection` (GarmentCode's "right_wrong") keeps the direction. A stitch between
// two edges of one panel is a dart.
struct Stitch {
  EdgeRef first, second;
  bool sameDirection = false;
};

struct SewingPattern {
  std::string name;
  std::vector<Panel> panels;
  std::vector<Stitch> stitches;
};

}  // namespace figment
