#include "sim/drape/DrapePlan.h"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "sim/core/ParameterChecks.h"
#include "sim/drape/LayerStart.h"
#include "sim/drape/MethodChoice.h"
#include "sim/progressive/Decimation.h"

namespace figment {

namespace {

// The tolerance's configuration onto the plan: its method onto the parameters, its body,
// its progressive mesh (made now, at the study's share of the sections) and schedule.
void planForTolerance(const DrapeAsk& ask, DrapePlan& plan) {
  if (!ask.table) throw std::invalid_argument("tolerance: no tradeoff table to choose from");
  DrapeRequest& request = plan.request;  // holds the garment now
  const MethodChoice choice = chooseMethod(*ask.table, ask.tolerance, ask.body, request.garment.vertices);
  DrapeMethod::parse(choice.picked.method).applyTo(request.parameters);
  request.parameters.validate();
  request.body = choice.body;
  request.progressive.reset();
  request.schedule = {};
  if (choice.picked.progressive != "off") {
    const TriangleMesh& garment = request.garment;
    request.progressive = decimate(
        garment,
        DecimationOptions{.targetFaces = static_cast<int>(std::lround(kStudyCoarseShare * garment.triangles.size()))});
    const ScheduleText s = parseScheduleText(choice.picked.progressive);
    request.schedule = {static_cast<int>(std::lround(s.beginShare * request.progressive->levels())), -1, s.rate};
  }
  DrapeReport& report = plan.report;
  report.picked = choice.picked.label();
  report.pickedDeviation = choice.picked.worstMeanDeviation;
  report.pickedBody = choice.picked.body;
  report.passedOver = choice.passedOver;
  report.body = choice.bodyDescription;
}

}  // namespace

DrapePlan planDrape(DrapeAsk ask) {
  requireNonNegative("tolerance", ask.tolerance);
  if (ask.sewing && ask.tolerance > 0.0)
    throw std::invalid_argument("tolerance: a sewn garment drapes by the engine's own fields (tolerance 0)");
  DrapePlan plan;
  plan.request = DrapeRequest{.garment = std::move(ask.garment),
                              .parameters = ask.parameters,
                              .body = ask.body.collider,
                              .progressive = std::move(ask.progressive),
                              .schedule = ask.schedule};
  plan.request.sewing = std::move(ask.sewing);
  plan.report.body = ask.body.description;
  if (ask.tolerance > 0.0) planForTolerance(ask, plan);
  const ClothParameters& p = plan.request.parameters;
  plan.report.method = DrapeMethod::of(p);
  plan.report.strainLimit = p.strainLimit;
  plan.report.maxTime = p.maxTime;
  plan.report.triangles = static_cast<int>(plan.request.garment.triangles.size());
  if (plan.request.body && plan.request.body->moves()) plan.request.body->advanceTo(0.0);
  // Over garments already draped a whole-garment drape starts clean over them, and a sewn
  // one's panels are placed clean over them (its rest shape is its flat panels, so where its
  // panels start is all its garment's points say: a waistband placed at the skin, inside a
  // T-shirt beneath, tore pulling out). A progressive drape starts from its coarse level.
  if (ask.body.beneath && !plan.request.progressive) {
    LayerStart start = startOverLayers(plan.request.garment, *ask.body.beneath, p.clearance);
    plan.report.startedOverLayers = start.moved;
    if (start.moved > 0 && plan.request.sewing)
      plan.request.garment.vertices = std::move(start.positions);
    else if (start.moved > 0)
      plan.request.start = std::move(start.positions);
  }
  return plan;
}

GarmentDrape drape(DrapePlan plan, const DrapeObservers& observers) {
  DrapeRequest& request = plan.request;
  request.stepObserver = observers.step;
  request.progress = observers.progress;
  request.progressInterval = observers.progressInterval;
  if (request.body && request.body->moves())
    request.bodyClock = [moving = request.body](double time) { moving->advanceTo(time); };
  GarmentDrape out = drapeGarment(request);
  DrapeReport report = std::move(plan.report);
  report.run = out.report.run;
  report.level = out.report.level;
  report.levels = out.report.levels;
  report.sections = out.report.sections;
  report.settling = out.report.settling;
  report.wallSeconds = out.report.run.wallSeconds;
  out.report = std::move(report);
  return out;
}

}  // namespace figment
