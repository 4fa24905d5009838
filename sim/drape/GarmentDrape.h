#pragma once
// One garment's drape from plain data: the garment, its parameters, the body to collide
// with and, when draped level by level, its progressive mesh and schedule; out come
// where every rest point rests and what the run did. ClothEngine (nodes/cloth) reads
// its fields and chooses the method, then asks this; a front end without Coin asks it
// directly.

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "sim/cloth/ClothParameters.h"
#include "sim/cloth/ClothSolver.h"
#include "sim/collision/Collider.h"
#include "sim/core/TriangleMesh.h"
#include "sim/drape/DrapeReport.h"
#include "sim/pattern/Sewing.h"
#include "sim/progressive/ProgressiveDrape.h"
#include "sim/progressive/ProgressiveMesh.h"

namespace figment {

// A pattern's panels to sew before the drape (sim/pattern/Sewing.h): the request's garment
// is then the panels, cut and placed around the body but not yet sewn.
struct DrapeSewing {
  std::vector<Vec2> flat;                 // per garment node: its panel coordinates (m), the rest shape
  std::vector<std::array<int, 2>> seams;  // the node pairs the stitches pull together
  SewingParameters parameters{};
};

// What the sewing did, beside the drape that followed it.
struct SewingOutcome {
  DrapeResult run;                 // the sewing's steps (gravity off, until every seam closed)
  double closedGap = 0.0;          // m: the largest gap of a pair when it was merged
  double seamGap = 0.0;            // m: the largest gap across any seam at the drape's end
  int openPairs = 0;               // seam pairs not closed while sewing (drawn on through the drape)
  std::vector<int> openSeamPairs;  // which: indices into DrapeSewing::seams
  int sewnNodes = 0;               // nodes once the closed seams were merged
  int droppedTriangles = 0;        // triangles merging folded to a line (a dart's apex)
};

struct DrapeRequest {
  TriangleMesh garment{};  // its rest shape, which is also where the drape starts (unless sewn or `start`)
  // Set: where a whole-garment drape starts, one position per node (over the layers
  // beneath: sim/drape/LayerStart.h); the garment stays its rest shape.
  std::optional<std::vector<Vec3>> start{};
  ClothParameters parameters{};
  std::shared_ptr<const Collider> body{};
  // Set: the garment is draped level by level from this mesh (paper §4), by `schedule`.
  std::optional<ProgressiveMesh> progressive{};
  ProgressiveSchedule schedule{};
  // Called before the first step and after every step of a whole-garment drape (a
  // progressive drape's solver changes with its level and is not observed).
  ClothSolver::StepObserver stepObserver{};
  // Set: the body moves during the drape (sim/collision/MovingMeshCollider.h); called
  // with the simulated time before the first step and after every step, before
  // stepObserver. A whole-garment drape only: with `progressive` set it is refused.
  std::function<void(double time)> bodyClock{};
  // Called about every `progressInterval` s of wall time (0: every 64 steps).
  std::function<void(const DrapeProgress&)> progress{};
  double progressInterval = 1.0;
  // Set: the garment's panels are sewn first, then draped (a whole-garment drape only),
  // resting as its flat panels.
  std::optional<DrapeSewing> sewing{};
};

struct GarmentDrape {
  std::vector<Vec3> positions;     // every rest point's
  std::vector<Triangle> sections;  // those simulated last, in the garment's numbering
  // The run, its triangles and sections, a progressive drape's levels and settling; what
  // chose the method is the plan's to add (sim/drape/DrapePlan.h).
  DrapeReport report;
  std::optional<SewingOutcome> sewing;  // sewn only
};

// Throws SimulationError (sim/cloth/ClothSolver.h) when the simulation blows up, and
// std::invalid_argument naming the parameter when one cannot be used (or a moving body
// with a progressive or sewn drape, or sewing with a progressive mesh).
GarmentDrape drapeGarment(const DrapeRequest& request);

}  // namespace figment
