#pragma once
// Cross sections of a body mesh (metres, y up) and the landmarks a garment generator
// needs from them: the torso's convex outline at a height, the armpits, the neck.
// Formulas and sources at the top of BodySlices.cpp.

#include <Eigen/Core>
#include <vector>

#include "sim/core/TriangleMesh.h"

namespace figment {

using Vec2 = Eigen::Vector2d;

struct Segment2 {
  Vec2 a, b;
};

enum class SectionAxis { X, Y, Z };

// The convex hull of `points` (Andrew's monotone chain), counter-clockwise, without
// repeated or collinear points; fewer than 3 points come back as given (deduplicated).
std::vector<Vec2> convexHull(std::vector<Vec2> points);

// Cuts `mesh` with the plane {p[axis] = value}: one segment per triangle that crosses it
// (edge crossings, so a section is as fine as the mesh's edges, not only its vertices).
// Coordinates in the plane: (x, z) for Y, (z, y) for X, (x, y) for Z.
std::vector<Segment2> planeSection(const TriangleMesh& mesh, SectionAxis axis, double value);

// Section segments grouped into runs along x: sorted by their smallest x, a new cluster starts
// wherever the next segment begins more than `gap` (m) beyond the x the cluster reaches. An arm
// and the torso beside it fall apart; a long segment across a flat face keeps its ends together.
struct XCluster {
  double minX = 0, maxX = 0;  // m
  std::vector<Vec2> points;   // the segments' ends
};
std::vector<XCluster> clusterByX(std::vector<Segment2> segments, double gap);

struct SliceOptions {
  double clusterGap = 0.04;      // m; ~2x the default body's edge length (2 cm splits a limb)
  double torsoHalfWidth = 0.12;  // m; clusters reaching |x - torsoCentreX| <= this are torso or legs
  double torsoCentreX = 0.0;     // m
};

// The torso's horizontal section at one height: the convex hull, in (x, z), of the section
// points of the clusters that reach the torso band (the torso, or both legs below the crotch;
// not the arms or hands). The hull spans the gap between the legs and the cleavage the way a
// tube of cloth does.
struct TorsoSlice {
  double height = 0;       // m
  std::vector<Vec2> hull;  // (x, z), counter-clockwise in those coordinates, no repeats

  bool empty() const { return hull.size() < 3; }
  Vec2 centroid() const;  // area centroid
  bool contains(const Vec2& p) const;
  double minX() const;
  double maxX() const;
  // The distance t along the unit `direction` from `origin` (inside the hull) to the point
  // that lies `clearance` (m, >= 0) outside the hull: the offset hull's boundary. With a
  // clearance of 0, where the ray leaves the hull.
  double reach(const Vec2& origin, const Vec2& direction, double clearance = 0.0) const;
};

TorsoSlice sliceTorso(const TriangleMesh& body, double height, const SliceOptions& options = {});

// Slicing options for `body` (not empty) centred on its bounding box in x, as garment
// generators use them.
SliceOptions centredSlicing(const TriangleMesh& body, double clusterGap, double torsoHalfWidth);

// The height (m) just below which the arms part from the torso: the highest height, below
// the widest torso section between 50% and 90% of the body's height (there the arms join
// it), at which torso-band clusters have a separate cluster on each side. Found to 1 mm.
// Throws std::invalid_argument when the arms never part from the torso.
double armpitHeight(const TriangleMesh& body, const SliceOptions& options = {});

// The height (m) of the narrowest torso-band section between the armpits and where the head
// starts to widen again (by more than 1.5 cm): the neck. The body's top when there is no head.
double neckHeight(const TriangleMesh& body, double armpit, const SliceOptions& options = {});

}  // namespace figment
