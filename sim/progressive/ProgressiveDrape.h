#pragma once
// A progressive drape (paper §4): the garment is simulated at a coarse level of its
// progressive mesh first and vertex splits bring it back to detail as it drapes.
//
// Schedule: the drape begins at `beginLevel` (splits applied before it starts) and
// ends at `endLevel`. With splitsPerSecond > 0 the splits are due at that rate of
// simulated time; with 0, all remaining splits come at once when the current level
// has come to rest (the paper's two stages). Due splits are applied in batches of at
// least a tenth of the way (each batch rebuilds the solver for the new level, about
// what a few steps cost), the last batch whatever its size. The drape is at rest when
// the end level is.
//
// Each split restores its sections' rest geometry (so their strain is right from the
// start) and places its vertices from the deformed neighbourhood (SplitPlacement.h).
// Each level's density is scaled so the garment's mass is the full garment's at every
// level. The time step stays the scene's: the implicit integrator is stable at any,
// and an explicit one must be stable for the finest level anyway.

#include "sim/cloth/ClothSolver.h"
#include "sim/progressive/ProgressiveMesh.h"

#include <memory>

namespace figment {

struct ProgressiveSchedule {
  int beginLevel = 0;
  int endLevel = -1;            // -1: every split (the full garment)
  double splitsPerSecond = 0.0;  // of simulated time; 0: the rest at once when the level rests
};

class ProgressiveDrape {
 public:
  // `mesh` is kept by reference.
  ProgressiveDrape(const ProgressiveMesh& mesh, const ClothParameters& parameters,
                   std::shared_ptr<const Collider> body, const ProgressiveSchedule& schedule);

  // One step of the current level's solver, then the splits due.
  void step();
  // Steps until the end level rests or maxTime; `progress` as ClothSolver::run's.
  DrapeResult run(const std::function<void(const DrapeProgress&)>& progress = {}, double progressInterval = 1.0);
  bool atRest() const { return level_.level() == endLevel_ && solver_->atRest(); }

  int level() const { return level_.level(); }
  int endLevel() const { return endLevel_; }
  int sections() const { return static_cast<int>(solver_->model().sections().size()); }
  const ClothSolver& solver() const { return *solver_; }
  // The garment's total mass now, kg.
  double mass() const;
  // Every vertex of the full garment: the active ones as draped, the others where the
  // remaining splits would put them.
  std::vector<Vec3> fullPositions() const;
  // The current level's sections, in the full garment's vertex numbering.
  std::vector<Triangle> levelTriangles() const;

 private:
  void splitTo(int target);
  void rebuild();
  int dueLevel() const;

  const ProgressiveMesh& mesh_;
  ClothParameters parameters_;
  std::shared_ptr<const Collider> body_;
  ProgressiveSchedule schedule_;
  int endLevel_, batch_;
  double fullArea_;
  MeshLevel level_;
  std::vector<int> fullIndex_;           // per solver node, its full vertex
  std::vector<Vec3> x_, v_;              // per full vertex (the active ones meaningful)
  std::unique_ptr<ClothSolver> solver_;
  ImplicitStepCosts retiredCosts_;       // of the solvers of earlier levels
};

}  // namespace figment
