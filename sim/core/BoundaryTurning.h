#pragma once
// How a garment's free boundary turns at each of its vertices, split into the turning
// within the cloth and the bending with it. The 3D turning (BoundaryLoops.h: the angle
// between consecutive boundary edges) mixes two things: a cut that zig-zags across the
// cloth's triangles (what a jagged hem is) and a hem that follows the cloth as it folds or
// wraps a body (what a drape is). A hem rolled round a cylinder turns in 3D at every vertex
// while it runs straight along the cloth.
//
// At a boundary vertex v with edges p -> v -> q along its loop (BoundaryLoops.h: wound as the
// triangles are, so the cloth lies on the loop's left seen from the side they face):
//   - geodesic turning  kg = pi - sum of the angles at v of the triangles between v -> q and
//     p -> v (the fan through the cloth): 0 where the cloth makes a straight angle, 2 pi / n
//     at each corner of a regular n-gon, -2 pi / n round a regular n-gon hole; positive where
//     the boundary turns towards the cloth. It is the discrete geodesic curvature of the
//     boundary (the boundary term of the discrete Gauss-Bonnet theorem: over a disc's loop
//     sum kg = 2 pi - sum of the inner vertices' angle defects, 2 pi for a flat one). It
//     depends on the triangles' edge lengths alone, so a drape that does not stretch the
//     cloth cannot change it: a fold or a roll leaves it as cut;
//   - normal turning  kn = sqrt(max(t^2 - kg^2, 0)) for the 3D turning t: the rest, the
//     bending with the cloth. For a smooth curve on a surface the curvature vector splits
//     into kg along the surface's side direction and kn along its normal, |k|^2 = kg^2 + kn^2;
//     the discrete parts keep that split. t >= kg always (the 3D angle between the two
//     edges is at most the angle through the cloth), but t may be less than -kg: a hole's rim
//     gathered straight by a ruffle. kn is then 0.
// A zig-zag is a geodesic turning whose sign alternates from vertex to vertex. Its share is
// the part of the boundary's 3D turning (summed over its vertices) that is the geodesic
// turning of vertices whose sign differs from both their neighbours' along the loop: 0 for
// a convex or smoothly waving loop, about 1 for a flat saw tooth. Weighed against the 3D
// turning rather than the geodesic: a hem that runs straight within the cloth round a body
// has next to no geodesic turning, and a drape's strain adds noise to it that alternates in
// sign, which against its own size would read as a zig-zag.
// Based on: the discrete Gauss-Bonnet theorem for a surface with boundary, whose boundary
// term is pi minus the angle sum (e.g. Crane, "Discrete Differential Geometry: An Applied
// Introduction", 2018); Polthier & Schmies, "Straightest geodesics on polyhedral surfaces"
// (1998), on a polyhedral curve's geodesic curvature as an angle; do Carmo, "Differential
// Geometry of Curves and Surfaces" (1976) §4-5, for a curve's curvature as kg and kn.

#include <vector>

#include "sim/core/TriangleMesh.h"

namespace figment {

class BoundaryTurning {
 public:
  // A turning's three angles, degrees: one vertex's (Turn) or their medians (Summary).
  struct Angles {
    double total = 0.0;     // the 3D turning, 0 to 180
    double geodesic = 0.0;  // signed: positive towards the cloth
    double normal = 0.0;    // >= 0
  };

  // One boundary vertex's turning.
  struct Turn : Angles {
    int vertex = 0;
  };

  // Medians over every boundary vertex (of |geodesic|), and the zig-zag share.
  struct Summary : Angles {
    int vertices = 0;
    double zigZagShare = 0.0;
  };

  // The boundary loops of `triangles` (boundaryLoops) and, at each loop vertex, the
  // triangles of its fan through the cloth. `triangles` must wind consistently; where a
  // fan cannot be walked edge to edge (a non-manifold edge), it is every triangle at the
  // vertex.
  explicit BoundaryTurning(const std::vector<Triangle>& triangles);

  const std::vector<std::vector<int>>& loops() const { return loops_; }

  // Each loop vertex's turning at `positions` (the rest shape or a drape of it), loop by
  // loop in loops()' order.
  std::vector<std::vector<Turn>> turns(const std::vector<Vec3>& positions) const;

  Summary summary(const std::vector<Vec3>& positions) const;

  // For each loop vertex (as turns() orders them), degrees: how far the edge strains
  // between `rest` and `deformed` can move its geodesic turning, to first order. An angle C
  // of a triangle with angles A, B at its other corners moves by
  //   dC = (cot A + cot B) e_c - cot B e_a - cot A e_b
  // for log strains e of the sides opposite A, B, C; with |e| <= the triangle's largest
  // |strain|, |dC| <= (|cot A + cot B| + |cot A| + |cot B|) max |e|, summed over the fan
  // (cotangents at `rest`).
  std::vector<double> geodesicStrainAllowance(const std::vector<Vec3>& rest, const std::vector<Vec3>& deformed) const;

  // The share of `turns`' 3D turning that zig-zags within the cloth (see above).
  static double zigZagShare(const std::vector<std::vector<Turn>>& turns);

  // The median of `values` (0 for none).
  static double median(std::vector<double> values);

 private:
  std::vector<Triangle> triangles_;
  std::vector<std::vector<int>> loops_;
  std::vector<std::vector<std::vector<int>>> fans_;  // per loop, per vertex: triangle indices
};

}  // namespace figment
