#pragma once
// One flat panel cut into triangles: its outline's points kept exactly as given (so the
// two sides of a seam keep the same nodes), interior nodes on a regular triangular
// lattice of spacing h, and a constrained Delaunay triangulation of both (CDT,
// cmake/FetchCdt.cmake) with the outline's segments as constraints and the triangles
// outside the outline erased. Concave outlines (an L, a sleeve cap, a dart's notch) are
// cut as they are.
//
// Why a lattice: equilateral triangles of side h inside (angles of 60 degrees, the
// cloth model's best case), and node spacing that matches the outline's sampling; a
// lattice node closer than h/2 to the outline is dropped, so no sliver is left between
// the lattice and the outline.

#include <array>
#include <vector>

#include "sim/pattern/SewingPattern.h"

namespace figment {

struct PanelMesh {
  // Panel coordinates (m): the outline's points first, in the order given (each edge's
  // shared end point once), then the interior lattice nodes.
  std::vector<Vec2> points;
  // Counter-clockwise in the panel's (u, v) plane, whichever way the outline runs.
  std::vector<std::array<int, 3>> triangles;
  // Per edge: its nodes' indices into `points`, from the edge's start to its end (both
  // included; the last of edge k is the first of edge k + 1, the last edge's last is the
  // first edge's first).
  std::vector<std::vector<int>> edgeNodes;
  int outlineCount = 0;  // how many of `points` are on the outline
};

// Triangulates a panel whose closed outline is `edges`: per edge, its points from start
// to end (at least 2 each, e.g. sampleEdge's), edge k's last point equal to edge k + 1's
// first (within 1e-9 m, and the last edge's last to the first edge's first). `spacing`
// (m, > 0) is the interior lattice's spacing h. The outline may run either way round.
// Throws std::invalid_argument for a bad spacing, an outline of fewer than 3 points, edges
// that do not meet, or an outline that touches or crosses itself.
PanelMesh meshPanel(const std::vector<std::vector<Vec2>>& edges, double spacing);

}  // namespace figment
