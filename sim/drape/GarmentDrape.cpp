#include "sim/drape/GarmentDrape.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <utility>

namespace figment {

namespace {

GarmentDrape drapeWhole(const DrapeRequest& request) {
  ClothSolver solver = request.start
                           ? ClothSolver(*request.start, RestShape(request.garment), request.parameters, request.body)
                           : ClothSolver(request.garment, request.parameters, request.body);
  if (request.bodyClock)
    solver.setStepObserver([&request](const ClothSolver& s) {
      request.bodyClock(s.time());
      if (request.stepObserver) request.stepObserver(s);
    });
  else if (request.stepObserver)
    solver.setStepObserver(request.stepObserver);
  GarmentDrape out;
  out.report.run = solver.run(request.progress, request.progressInterval);
  out.positions = solver.positions();
  out.sections = request.garment.triangles;
  return out;
}

// Per panel node, where its sewn node is.
std::vector<Vec3> panelPositions(const SewnGarment& sewn, const std::vector<Vec3>& x) {
  std::vector<Vec3> out;
  out.reserve(sewn.nodeOf.size());
  for (int node : sewn.nodeOf) out.push_back(x[node]);
  return out;
}

// Sews the panels, then drapes what was sewn. Seams that did not close while sewing go on
// pulling, with gravity, as hard as at the sewing's end, until they come within half the
// merging reach, or within the reach and no longer closing (the sewing's stall rule), or the
// run's time is out; then they are merged too, and the garment drapes to rest. Waiting for
// a pair held within the reach (a back seam 4.7 cm apart across the women's shirt XXL) only
// held its cloth stretched for the rest of the run: it merges either way.
GarmentDrape drapeSewn(const DrapeRequest& request) {
  const DrapeSewing& sewing = *request.sewing;
  const UnsewnGarment panels{request.garment, sewing.flat, {}, {}, sewing.seams, {}};
  // A sewn top closes and rests round the armpits, whose creases left nodes inside the arm
  // (ImplicitSolverParameters::leaveCreases).
  ClothParameters parameters = request.parameters;
  parameters.implicitSolver.leaveCreases = true;
  SewnGarment sewn = sewPanels(panels, parameters, request.body, sewing.parameters);
  SewingOutcome outcome;
  outcome.run = sewn.sewing;
  outcome.closedGap = sewn.closedGap;
  int steps = 0;
  double time = 0.0, wall = 0.0;
  if (!sewn.openPairs.empty()) {
    const auto started = std::chrono::steady_clock::now();
    // The pulling's steps stay the scene's, as the sewing's do: its stall rule counts them.
    ClothParameters pulled = parameters;
    pulled.implicitSolver.maxTimeStep = 0.0;
    ClothSolver pulling(sewn.positions, sewn.rest, pulled, request.body,
                        SeamPull{sewn.openSeams, sewing.parameters.rate * sewn.strength});
    const SewingParameters& rule = sewing.parameters;
    double gap = pulling.model().seams().largestGap(pulling.positions());
    StallCount stall(rule);
    while (gap > 0.5 * rule.snapGap && pulling.time() < parameters.maxTime - 1e-12) {
      pulling.step();
      const double before = gap;
      gap = pulling.model().seams().largestGap(pulling.positions());
      const bool stalled = stall.stalledAfter(before, gap);  // counted on every step
      if (gap <= rule.snapGap && stalled) break;
    }
    steps = pulling.iterations(), time = pulling.time();
    wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    SewnGarment closer = mergeSeams(panels, panelPositions(sewn, pulling.positions()), sewing.parameters.snapGap);
    closer.strength = sewn.strength;
    outcome.closedGap = std::max(outcome.closedGap, closer.closedGap);
    sewn = std::move(closer);
  }
  ClothSolver solver(sewn.positions, sewn.rest, parameters, request.body,
                     SeamPull{sewn.openSeams, sewing.parameters.rate * sewn.strength});
  if (request.stepObserver) solver.setStepObserver(request.stepObserver);
  GarmentDrape out;
  out.report.run = solver.run(request.progress, request.progressInterval);
  out.report.run.iterations += steps;
  out.report.run.simulatedTime += time;
  out.report.run.wallSeconds += wall;
  out.positions = panelPositions(sewn, solver.positions());
  out.sections = request.garment.triangles;
  outcome.seamGap = largestSeamGap(panels, out.positions);
  outcome.openPairs = static_cast<int>(sewn.openPairs.size());
  outcome.openSeamPairs = sewn.openPairs;
  outcome.sewnNodes = static_cast<int>(sewn.positions.size());
  outcome.droppedTriangles = sewn.droppedTriangles;
  out.sewing = outcome;
  return out;
}

GarmentDrape drapeProgressively(const DrapeRequest& request) {
  ProgressiveDrape drape(*request.progressive, request.parameters, request.body, request.schedule);
  GarmentDrape out;
  out.report.run = drape.run(request.progress, request.progressInterval);
  out.positions = drape.fullPositions();
  out.sections = drape.levelTriangles();
  out.report.level = drape.level();
  out.report.levels = request.progressive->levels();
  out.report.settling = drape.endLevelSettling();
  return out;
}

}  // namespace

GarmentDrape drapeGarment(const DrapeRequest& request) {
  if (request.bodyClock && request.progressive)
    throw std::invalid_argument("a body that moves into its pose needs a whole-garment drape, not a progressive one");
  if (request.sewing) {
    if (request.progressive) throw std::invalid_argument("a sewn garment drapes whole, not progressively");
    if (request.bodyClock) throw std::invalid_argument("a sewn garment drapes on a body already in its pose");
  }
  GarmentDrape out = request.sewing        ? drapeSewn(request)
                     : request.progressive ? drapeProgressively(request)
                                           : drapeWhole(request);
  out.report.method = DrapeMethod::of(request.parameters);
  out.report.strainLimit = request.parameters.strainLimit;
  out.report.maxTime = request.parameters.maxTime;
  out.report.triangles = static_cast<int>(request.garment.triangles.size());
  out.report.sections = static_cast<int>(out.sections.size());
  return out;
}

}  // namespace figment
