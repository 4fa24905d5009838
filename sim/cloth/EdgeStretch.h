#pragma once
// How far a garment's edges are stretched: each edge's length over its rest length.
// What a drape's verdict reads at its end (sim/cloth/DrapeVerdict.h: an edge past the
// tear bound) and what the implicit step's control reads after each step (an edge whose
// strain grew too much in one step: the linearised step failed, ClothSolver.h).

#include <array>
#include <vector>

#include "sim/cloth/RestShape.h"
#include "sim/core/TriangleMesh.h"

namespace figment {

class EdgeStretch {
 public:
  // The edges of `rest`'s triangles, each once; an edge of zero rest length is left out
  // (its stretch is undefined; a degenerate section carries no force either).
  explicit EdgeStretch(const TriangleMesh& rest);
  // The same for a rest shape (sim/cloth/RestShape.h): a sewn garment's flat pieces.
  explicit EdgeStretch(const RestShape& rest);
  EdgeStretch() = default;  // no edges

  // max over the edges of |x_a - x_b| / L_ab, dimensionless (1: at rest length); 1 for a
  // garment without edges. `x` has one position per rest vertex (m).
  double largest(const std::vector<Vec3>& x) const;
  // Whether some edge jumped between two states: ends `after` stretched past `bound` with
  // its stretch grown by more than `growth` since `before`, or ends not finite.
  bool jumped(const std::vector<Vec3>& before, const std::vector<Vec3>& after, double bound, double growth) const;

  size_t edgeCount() const { return edges_.size(); }

 private:
  double stretch(size_t edge, const std::vector<Vec3>& x) const;

  std::vector<std::array<int, 2>> edges_;
  std::vector<double> restLengths_;  // m, > 0
};

}  // namespace figment
