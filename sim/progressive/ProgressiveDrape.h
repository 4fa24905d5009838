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
// level. The time step: the implicit integrator keeps the scene's (stable at any); an
// explicit one takes a coarser level's longer stability bound, up to twice the scene's
// step (ProgressiveDrape.cpp, stabilityTime: the shortest sqrt(m/k) of the level's
// nodes against the full garment's; on the default dress's coarsest level 3.3x, but
// Heun with the 30 g clamp then never rests there at 2.5x and more), and maxTime is
// counted in simulated time.

#include <memory>
#include <utility>
#include <vector>

#include "sim/cloth/ClothSolver.h"
#include "sim/progressive/ProgressiveMesh.h"

namespace figment {

// How much longer a coarse level's explicit step may be than the scene's (so a run of one
// coarse step needs maxTime this many scene steps).
constexpr double kMaxStepGrowth = 2.0;

// What happened after the last split: when the end level arrived (simulated s; -1 if
// it never did) and how far the garment moved from its placed state at that moment to
// where the run ended (mean and largest over the end level's vertices, m). A coarse
// level whose rest shape the fine one keeps moves little and rests soon after.
struct EndLevelSettling {
  double arrival = -1.0;
  double meanMove = 0.0, maxMove = 0.0;
};

struct ProgressiveSchedule {
  int beginLevel = 0;
  int endLevel = -1;             // -1: every split (the full garment)
  double splitsPerSecond = 0.0;  // of simulated time; 0: the rest at once when the level rests
};

class ProgressiveDrape {
 public:
  // `mesh` is kept by reference.
  ProgressiveDrape(const ProgressiveMesh& mesh, const ClothParameters& parameters, std::shared_ptr<const Collider> body,
                   const ProgressiveSchedule& schedule);

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
  // After the last split, so far.
  EndLevelSettling endLevelSettling() const;

 private:
  // Applies splits up to `target`; returns the vertices they placed.
  std::vector<int> splitTo(int target);
  // Makes the placed state fit to simulate. A coarse section resting on convex skin
  // cuts a chord through it, so a split puts its vertices under the skin (the explicit
  // contact response would turn that depth into speed); and where a coarse section bent
  // across a fold or a strap's edge, the new sections start stretched far beyond
  // anything the drape makes (which put light strap nodes of Heun's drape on the edge of
  // its stability: it blew up). So: placed vertices inside the body or its clearance go
  // to the surface + clearance without velocity into it, and the level's edges are
  // pulled or pushed back to within kSettledStrain of their rest lengths (Gauss-Seidel
  // sweeps, as strain limiting does), in turns.
  void settle(const std::vector<int>& placed);
  // Sweeps over `edges`; returns the vertices it moved.
  std::vector<int> relaxStrain(const std::vector<std::pair<int, int>>& edges);
  void liftOutOfBody(const std::vector<int>& vertices);
  void rebuild();
  int dueLevel() const;

  const ProgressiveMesh& mesh_;
  ClothParameters parameters_;
  std::shared_ptr<const Collider> body_;
  ProgressiveSchedule schedule_;
  int endLevel_, batch_;
  double fullArea_, fullStabilityTime_;
  MeshLevel level_;
  std::vector<int> fullIndex_;        // per solver node, its full vertex
  std::vector<Vec3> x_, v_;           // per full vertex (the active ones meaningful)
  double endLevelArrival_ = -1.0;     // simulated s
  std::vector<Vec3> endLevelPlaced_;  // per solver node, as the end level began
  std::unique_ptr<ClothSolver> solver_;
  ImplicitStepCosts retiredCosts_;  // of the solvers of earlier levels
};

}  // namespace figment
