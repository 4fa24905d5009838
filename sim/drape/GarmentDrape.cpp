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
  return request.progressive ? drapeProgressively(request) : drapeWhole(request);
}

}  // namespace figment
