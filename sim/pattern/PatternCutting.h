#pragma once
// A sewing pattern cut into cloth (sim/pattern/UnsewnGarment.h): each edge sampled by arc
// length, each panel triangulated in its plane (sim/pattern/PanelMesh.h) and placed
// around the body, and the stitches turned into the node pairs a seam pulls together.
//
// Both edges of a stitch get the same number of segments, so node k of one lies at the
// same fraction of arc length as its partner on the other: seams close without shear.
// Edges joined through several stitches (an edge sewn to two others) all get the largest
// count among them.
//
// Orientation (GarmentCode's convention, checked on every shipped pattern): the fabric's
// right side faces out when the panel's outline runs counter-clockwise seen from outside.
// A panel whose outline runs counter-clockwise in (u, v) has its right side towards
// rotation (0, 0, 1) (the front panels, +z); a clockwise one away from it (the back panels,
// whose rotation is the identity too). The triangles are made counter-clockwise seen from
// the right side, so their normals point out of the garment.

#include <vector>

#include "sim/pattern/SewingPattern.h"
#include "sim/pattern/UnsewnGarment.h"

namespace figment {

// Per panel, per edge: how many segments the edge is cut into at node spacing `spacing`
// (m): ceil(arc length / spacing), at least 1, and for stitched edges the largest such
// count among all the edges their stitches join.
std::vector<std::vector<int>> edgeSegments(const SewingPattern& pattern, double spacing);

// Cuts every panel at node spacing `spacing` (m, > 0; the outline's segments are at most
// that long, the interior lattice's triangles equilateral of that side). Seams: per stitch,
// node k of its first edge with node n - k of its second (node k when `sameDirection`),
// n its segment count; a node paired with itself (a dart's tip, where its two edges meet)
// is no seam and left out. Throws std::invalid_argument naming the panel, edge or stitch:
// a stitch naming a missing panel or edge or sewing an edge to itself, an edge whose end
// points are missing or do not join its neighbours, a placement that is not a rotation,
// an outline that touches or crosses itself.
UnsewnGarment cutPattern(const SewingPattern& pattern, double spacing);

}  // namespace figment
