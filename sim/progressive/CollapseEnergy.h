#pragma once
// What an edge collapse costs (paper §4, after Hoppe 1996): the three candidates per
// edge (into either end vertex or into the midpoint), each scored by
//
//   E = E_surface + E_perimeter + E_homogeneity
//
//   E_surface     the squared distance of the original surface from the result, as
//                 Garland & Heckbert's quadrics: each vertex carries the planes of the
//                 original sections it stands for, weighted by their areas (m^4);
//   E_perimeter   the same for the perimeter (hems, necklines, armholes): planes through
//                 each original boundary edge, across its section, weighted by
//                 `perimeterWeight` times its squared length;
//   E_homogeneity `homogeneity` times the sum of the squared areas of the sections
//                 around the result: small sections go first, so a flat region coarsens
//                 evenly instead of into a few large sections beside many small ones.
//
// A candidate is refused where the result would be invalid: a non-manifold edge (the
// link condition), a boundary vertex moved off the boundary or two boundaries joined,
// a section turned by more than `maxTurn` from its original orientation (a fold-over),
// or a section thinner than `minQuality` (4 sqrt(3) area / sum of squared edges: 1 for
// an equilateral one).

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "sim/progressive/CollapseNeighbourhood.h"

namespace figment {

struct DecimationOptions {
  int targetFaces = 0;  // stop at this many sections, or where nothing may collapse
  double perimeterWeight = 10.0;
  double homogeneity = 0.05;
  double maxTurnDegrees = 45.0;
  double minQuality = 0.25;
};

struct Collapse {
  int kept = -1, removed = -1;
  Vec3 position;
  double cost = 0.0;
};

class CollapseEnergy {
 public:
  CollapseEnergy(const TriangleMesh& garment, const DecimationOptions& options);

  // The cheapest valid candidate for edge (a, b), if any.
  std::optional<Collapse> best(const CollapseNeighbourhood& mesh, int a, int b) const;
  // After the collapse: the kept vertex stands for both.
  void merge(int kept, int removed) { quadric_[kept] += quadric_[removed]; }

 private:
  std::optional<double> cost(const CollapseNeighbourhood& mesh, int kept, int removed, const Vec3& p) const;

  DecimationOptions options_;
  std::vector<Eigen::Matrix4d> quadric_;  // per vertex
  std::vector<Vec3> originalNormal_;      // per face, unit
};

}  // namespace figment
