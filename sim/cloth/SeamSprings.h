#pragma once
// Seams being sewn: each pulls its two nodes together with a spring of zero rest length
// and a damper along it, the way garment tools close a pattern's seams (panels placed
// around the body, stitches pulled shut by the simulation):
//
//   f_a = k (x_b - x_a) + c (v_b - v_a),   f_b = -f_a                       (N)
//   K = -df/dx = k [I -I; -I I],  C = -df/dv = c [I -I; -I I]
//
// Linear, so backward Euler closes a gap of half a metre in a few large steps without
// overshoot, and the matrix stays positive semi-definite. k and c are per seam, scaled
// with the two nodes' mean mass m: k = rate m, c = 2 sqrt(rate) m (critical damping of the
// pair alone), so the closing does not depend on the mesh's resolution.

#include <array>
#include <vector>

#include "sim/cloth/ElementOutput.h"
#include "sim/core/TriangleMesh.h"

namespace figment {

// The seams a garment is being sewn along: node pairs, and how hard they pull.
struct SeamPull {
  std::vector<std::array<int, 2>> seams;
  double rate = 400.0;  // k / m, 1/s^2: a pair alone closes in about 1 / sqrt(rate) = 0.05 s
};

class SeamSprings {
 public:
  SeamSprings() = default;  // no seams
  // rate: k / m, 1/s^2 (> 0); masses: every node's (kg). Throws std::invalid_argument for a
  // node out of range, a seam from a node to itself, or a rate that is not > 0.
  SeamSprings(std::vector<std::array<int, 2>> seams, const std::vector<double>& masses, double rate);

  bool empty() const { return seams_.empty(); }
  size_t size() const { return seams_.size(); }
  const std::array<int, 2>& nodes(size_t seam) const { return seams_[seam]; }

  // Seam s's forces into out.force (its two nodes' order): the spring's when `elastic`,
  // the damper's when `damping`; with weights, its K v and its blocks (w_damping C +
  // w_stiffness K) into out as well.
  void evaluate(size_t seam, const std::vector<Vec3>& x, const std::vector<Vec3>& v, bool elastic, bool damping,
                const SystemWeights* weights, const ElementOutput& out) const;

  // Every seam's spring and damper `factor` times as stiff (> 0): a seam that stopped
  // closing against the cloth's own tension pulls harder.
  void strengthen(double factor);

  // The largest distance between a seam's two nodes at x (m); 0 without seams.
  double largestGap(const std::vector<Vec3>& x) const;

 private:
  std::vector<std::array<int, 2>> seams_;
  std::vector<double> stiffness_, damping_;  // N/m, N s/m, per seam
};

}  // namespace figment
