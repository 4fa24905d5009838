#pragma once
// A display mesh for a coarse drape: the simulation's triangles split four ways per level
// and the new vertices put on a smooth surface through the old ones, so a garment modelled
// with no more triangles than its drape needs is drawn with smooth hems and silhouettes.
//
// Interpolating (the simulation's vertices are drawn exactly where the drape put them; only
// the new vertices are placed), with two rules for a new vertex on edge a-b:
//   - an edge inside the surface: the edge's midpoint m pulled towards the tangent planes
//     of its ends, m + 1/4 sum_{i=a,b} ((x_i - m) . n_i) n_i, with n_i the unit vertex
//     normals (area weighted, averaged over vertices at the same position, so a seam is one
//     surface). On a sphere of radius R this is R(1 + O(phi^4)) from the centre for an edge
//     spanning 2 phi (the midpoint alone: R(1 - phi^2/2)); the move is at most a quarter of
//     the edge, so a crease cannot throw a vertex far;
//   - an edge of the free boundary (hem, sleeve end, neckline): the 4-point scheme along its
//     loop, 9/16 (x_a + x_b) - 1/16 (x_c + x_d) with c before a and d after b (Dyn, Levin &
//     Gregory 1987), which halves the turning from vertex to vertex at each level; the plain
//     midpoint where a or b is a corner (turning more than kCornerDegrees), which keeps a
//     strap's square end square instead of overshooting it.
// Based on: Dyn, Levin & Gregory, "A 4-point interpolatory subdivision scheme for curve
// design" (CAGD 1987); the tangent-plane projection of Boubekeur & Alexa, "Phong
// Tessellation" (SIGGRAPH Asia 2008), with the blend 1/2 that reproduces a circle to
// fourth order (their 3/4 overshoots it by phi^2/4); Loop's 1-to-4 split of a triangle.
// Unlike Loop's or the butterfly scheme, both rules are local to an edge and its loop, so
// an irregular vertex, a boundary vertex or a non-manifold edge needs no special stencil.

#include <vector>

#include "sim/core/TriangleMesh.h"

namespace figment {

class DisplaySubdivision {
 public:
  // A vertex turning (degrees between its two boundary edges) more than this is a corner.
  static constexpr double kCornerDegrees = 60.0;

  // The display mesh's layout for `triangles` over `vertexCount` vertices and `levels` >= 0
  // splits (0: the triangles as they are). Vertices at the same position in `weldAt` (the
  // positions the layout is made for) are one vertex of the display mesh.
  DisplaySubdivision(const std::vector<Triangle>& triangles, const std::vector<Vec3>& weldAt, int levels);

  // The display triangles, wound as the triangles they split, over displayVertexCount()
  // vertices: the first are the simulation's own, in their order.
  const std::vector<Triangle>& triangles() const { return triangles_.back(); }
  int displayVertexCount() const { return counts_.back(); }
  int vertexCount() const { return counts_.front(); }
  int levels() const { return static_cast<int>(edges_.size()); }

  // The display vertices' positions and unit normals for the simulation's `positions`
  // (as many as the layout was made for).
  void apply(const std::vector<Vec3>& positions, std::vector<Vec3>& points, std::vector<Vec3>& normals) const;

 private:
  struct Edge {
    int a, b;
    bool boundary;
  };
  std::vector<int> weld_;                             // each simulation vertex to its representative
  std::vector<std::vector<Triangle>> triangles_;      // per level, level 0 welded
  std::vector<std::vector<Edge>> edges_;              // per split: the edges in new-vertex order
  std::vector<std::vector<std::vector<int>>> loops_;  // per split: the boundary loops
  std::vector<int> counts_;                           // vertices per level
};

}  // namespace figment
