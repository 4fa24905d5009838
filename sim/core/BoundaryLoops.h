#pragma once
// A garment's free boundary (hems, sleeve ends, necklines, armholes) as closed loops, and
// how sharply it turns at each of its vertices: a hem that follows a smooth curve turns a
// little at every vertex (a regular n-gon 360/n degrees), one that zig-zags along a grid's
// triangles turns by tens of degrees back and forth.

#include <functional>
#include <vector>

#include "sim/core/TriangleMesh.h"

namespace figment {

// The boundary edges (used by one triangle) chained into loops, each in the direction the
// triangles wind them. A vertex where two loops touch starts a new loop at its second
// outgoing edge, so every boundary edge is in exactly one loop.
std::vector<std::vector<int>> boundaryLoops(const std::vector<Triangle>& triangles);

// Degrees between consecutive edges at each vertex of `loops` (0 where the boundary runs
// straight on, 180 where it doubles back), loop by loop, from `positions` (the rest shape or
// a drape of it). Edges of zero length have no direction and count as straight.
std::vector<double> boundaryTurningAngles(const std::vector<Vec3>& positions,
                                          const std::vector<std::vector<int>>& loops);

// The median of the boundary's turning angles (degrees) of `mesh` at `positions`; 0 for a
// closed mesh.
double medianBoundaryTurning(const std::vector<Vec3>& positions, const std::vector<Triangle>& triangles);

// `mesh` with its `count` longest boundary edges (fewer where it has fewer) split at their
// midpoints, each triangle on one split in two through its opposite corner: an opening gets
// more vertices (it reads as a curve) where decimation left it coarse, without refining the
// rest. New vertices follow the old ones; ties in length go to the lower vertex indices.
TriangleMesh withBoundaryEdgesSplit(const TriangleMesh& mesh, int count);

// Smooths `loop` as a curve: each vertex moved towards the middle of its two neighbours
// along the loop, then back out (Taubin's lambda|mu steps, which take out a zig-zag without
// shrinking the loop), `iterations` times, each time put back on the curve's surface by
// `onSurface` (the plane or sphere it was cut along). Spacing along the loop evens out too.
void smoothLoop(std::vector<Vec3>& positions, const std::vector<int>& loop, int iterations,
                const std::function<Vec3(const Vec3&)>& onSurface);

}  // namespace figment
