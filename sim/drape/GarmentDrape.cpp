#include "sim/drape/GarmentDrape.h"

#include <stdexcept>
#include <utility>

namespace figment {

namespace {

GarmentDrape drapeWhole(const DrapeRequest& request) {
  ClothSolver solver(request.garment, request.parameters, request.body);
  if (request.bodyClock)
    solver.setStepObserver([&request](const ClothSolver& s) {
      request.bodyClock(s.time());
      if (request.stepObserver) request.stepObserver(s);
    });
  else if (request.stepObserver)
    solver.setStepObserver(request.stepObserver);
  GarmentDrape out;
  out.run = solver.run(request.progress, request.progressInterval);
  out.positions = solver.positions();
  out.sections = request.garment.triangles;
  return out;
}

GarmentDrape drapeSewn(const DrapeRequest& request) {
  const DrapeSewing& sewing = *request.sewing;
  const UnsewnGarment panels{request.garment, sewing.flat, {}, {}, sewing.seams, {}};
  const SewnGarment sewn = sewPanels(panels, request.parameters, request.body, sewing.parameters);
  // Seams that did not close go on pulling through the drape, as hard as at the end.
  const SeamPull open{sewn.openSeams, sewing.parameters.rate * sewn.strength};
  ClothSolver solver(sewn.positions, sewn.rest, request.parameters, request.body, open);
  if (request.stepObserver) solver.setStepObserver(request.stepObserver);
  GarmentDrape out;
  out.run = solver.run(request.progress, request.progressInterval);
  out.positions.reserve(sewn.nodeOf.size());
  for (int node : sewn.nodeOf) out.positions.push_back(solver.positions()[node]);
  out.sections = request.garment.triangles;
  SewingOutcome outcome;
  outcome.run = sewn.sewing;
  outcome.closedGap = sewn.closedGap;
  outcome.seamGap = largestSeamGap(panels, out.positions);
  outcome.openPairs = static_cast<int>(sewn.openSeams.size());
  outcome.sewnNodes = static_cast<int>(sewn.positions.size());
  outcome.droppedTriangles = sewn.droppedTriangles;
  out.sewing = outcome;
  return out;
}

GarmentDrape drapeProgressively(const DrapeRequest& request) {
  ProgressiveDrape drape(*request.progressive, request.parameters, request.body, request.schedule);
  GarmentDrape out;
  out.run = drape.run(request.progress, request.progressInterval);
  out.positions = drape.fullPositions();
  out.sections = drape.levelTriangles();
  out.level = drape.level();
  out.levels = request.progressive->levels();
  out.settling = drape.endLevelSettling();
  return out;
}

}  // namespace

GarmentDrape drapeGarment(const DrapeRequest& request) {
  if (request.bodyClock && request.progressive)
    throw std::invalid_argument("a body that moves into its pose needs a whole-garment drape, not a progressive one");
  if (request.sewing) {
    if (request.progressive) throw std::invalid_argument("a sewn garment drapes whole, not progressively");
    if (request.bodyClock) throw std::invalid_argument("a sewn garment drapes on a body already in its pose");
    return drapeSewn(request);
  }
  return request.progressive ? drapeProgressively(request) : drapeWhole(request);
}

}  // namespace figment
