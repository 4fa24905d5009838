#pragma once
// Sewing a pattern's panels around a body (issue 44), as garment tools do: the panels
// start where the pattern places them, and the simulation pulls every seam shut (zero
// rest-length springs in the implicit step, sim/cloth/SeamSprings.h) with gravity off, the
// body holding the cloth out, pulling harder wherever a seam stops closing (a fitted
// waistband, a pencil skirt round spread legs: the cloth must stretch to close them); then
// the nodes of each seam are merged (a corner where several seams meet, once) and what is
// left is one garment, whose rest shape is still its flat panels (sim/cloth/RestShape.h):
// darts and curved seams shape it.
//
// A seam that does not close within the sewing's time is not merged: it stays a spring
// through the drape that follows, and its gap is reported (a seam left open).

#include <memory>
#include <vector>

#include "sim/cloth/ClothParameters.h"
#include "sim/cloth/ClothSolver.h"
#include "sim/cloth/RestShape.h"
#include "sim/cloth/SeamSprings.h"
#include "sim/collision/Collider.h"
#include "sim/pattern/UnsewnGarment.h"

namespace figment {

struct SewingParameters {
  double rate = 400.0;      // the seams' first pull, k / m (1/s^2; sim/cloth/SeamSprings.h)
  double closedGap = 2e-3;  // m: a seam pair this close is closed
  // A seam that stops closing (its largest gap shrank by less than `stall` of itself in
  // each of `stallSteps` steps) is pulling against the cloth's own tension, which a pull
  // scaled to the nodes' mass cannot outdo: the seams then pull `strengthen` times harder,
  // up to `maxStrength` times the first pull. At 3 % a gap creeping shut at 4 to 9 % a step
  // (the pencil skirt's waistband, from 20 cm) never counted as stalled: every shipped
  // pattern sewed to the 3 s bound (60 steps) and merged 1 to 3 cm gaps; at 10 % they close
  // in 30 to 45 steps, as clean (docs/patterns.md, Figures).
  double stall = 0.10;
  int stallSteps = 3;
  double strengthen = 4.0;
  double maxStrength = 4096.0;
  // m: when the sewing ends (every pair closed, or the pull at its strongest and stalled,
  // or maxTime), pairs this close are merged at their midpoint, the drape that follows
  // spreading the strain; pairs farther apart stay open (reported, and pulled on).
  double snapGap = 0.05;
  double maxTime = 3.0;  // s of simulated time to close every seam, at most
  // Throws std::invalid_argument naming the field and value when out of range.
  void validate() const;
};

// The sewing's stall rule, step by step: whether a seam's largest gap has shrunk by less
// than `stall` of itself in each of the last `stallSteps` steps. The sewing strengthens its
// pull on it; the pulling after the sewing (sim/drape/GarmentDrape.h) stops on it.
class StallCount {
 public:
  explicit StallCount(const SewingParameters& rule) : stall_(rule.stall), steps_(rule.stallSteps) {}
  // After a step that took the largest gap from `before` to `gap`.
  bool stalledAfter(double before, double gap) {
    count_ = gap > (1.0 - stall_) * before ? count_ + 1 : 0;
    return count_ >= steps_;
  }
  void restart() { count_ = 0; }

 private:
  double stall_;
  int steps_;
  int count_ = 0;
};

struct SewnGarment {
  std::vector<Vec3> positions;                // per sewn node, where the sewing left it (m)
  RestShape rest;                             // the sewn triangles, each resting as its flat panel
  std::vector<int> nodeOf;                    // per panel node (UnsewnGarment's numbering): its sewn node
  std::vector<std::array<int, 2>> openSeams;  // seam pairs not closed, in sewn nodes
  std::vector<int> openPairs;                 // the same pairs, as indices into the garment's seams
  double closedGap = 0.0;                     // m: the largest gap of a pair when it was merged
  double strength = 1.0;                      // how much harder than `rate` the seams pulled at the end
  DrapeResult sewing;                         // the sewing's run: steps, time, wall time
  int droppedTriangles = 0;                   // triangles that merging folded to a line (at a dart's apex)
};

// Sews `garment` around `body` (may be null): `parameters` are the drape's (implicit
// integrator), gravity and the rest rule set aside while sewing. Throws
// std::invalid_argument for a garment without seams or bad parameters, and
// SimulationError when the sewing blows up.
SewnGarment sewPanels(const UnsewnGarment& garment, const ClothParameters& parameters,
                      std::shared_ptr<const Collider> body, const SewingParameters& sewing = {});

// The garment with its seam pairs that lie within `within` (m) at `positions` (one per
// panel node) merged at their midpoints: what sewPanels ends with, and what a drape that
// began with seams open makes once they have come close (sim/drape/GarmentDrape.cpp).
SewnGarment mergeSeams(const UnsewnGarment& garment, const std::vector<Vec3>& positions, double within);

// The unsewn panels' rest shape: each triangle resting as it lies in its flat panel.
RestShape panelsAtRest(const UnsewnGarment& garment);

// The largest distance between the two nodes of any seam pair at `positions` (per panel
// node), m: what a drape of the sewn garment reports as its seams' largest gap.
double largestSeamGap(const UnsewnGarment& garment, const std::vector<Vec3>& positions);

}  // namespace figment
