#pragma once
// A drape in two calls, with no scene graph: planDrape decides what to run (the method,
// from the parameters or, with a tolerance, from the tradeoff table and the body; the body
// to collide with; a progressive mesh and schedule; the sewing), drape runs it and reports
// (sim/drape/DrapeReport.h). ClothEngine (nodes/cloth) turns its fields into a DrapeAsk and
// the plan's outcome into its outputs; a program without Coin asks the same two calls.

#include <functional>
#include <optional>

#include "sim/drape/DrapeBody.h"
#include "sim/drape/DrapeReport.h"
#include "sim/drape/GarmentDrape.h"
#include "sim/drape/MethodTable.h"

namespace figment {

// What is asked of a drape.
struct DrapeAsk {
  TriangleMesh garment;  // its rest shape, where it starts (unless sewn)
  ClothParameters parameters;
  DrapeBody body;
  // > 0: drape by the fastest configuration of `table` measured within this deviation,
  // % of the garment's height (sim/drape/MethodChoice.h), in place of the parameters'
  // method, `progressive` and `schedule`; `table` must then be given.
  double tolerance = 0.0;
  const MethodTable* table = nullptr;
  std::optional<ProgressiveMesh> progressive;  // the garment's, to drape level by level (paper §4)
  ProgressiveSchedule schedule;
  std::optional<DrapeSewing> sewing;  // its panels, to sew first (not with a tolerance)
};

struct DrapePlan {
  DrapeRequest request;  // no observers yet: drape() adds them
  // What was decided: method, strainLimit, maxTime, the choice (picked, passedOver ...),
  // the body, the garment's triangles; the run's fields are drape()'s.
  DrapeReport report;
};

// Throws std::invalid_argument naming the parameter and value that cannot be used (a
// negative tolerance, sewing with a tolerance), std::runtime_error when no configuration
// within the tolerance suits the body. A body that moves into its pose stands at its
// first keyframe once planned, as the drape starts on it.
DrapePlan planDrape(DrapeAsk ask);

// What a front end watches while it runs (each may be empty).
struct DrapeObservers {
  // Before the first step and after every step of a whole-garment drape.
  ClothSolver::StepObserver step;
  // About every `progressInterval` s of wall time (0: every 64 steps).
  std::function<void(const DrapeProgress&)> progress;
  double progressInterval = 1.0;
};

// Runs the plan; a body that moves into its pose follows the drape's clock. Throws as
// drapeGarment (sim/drape/GarmentDrape.h). The report is the plan's with the run's
// fields, its wallSeconds the run's.
GarmentDrape drape(DrapePlan plan, const DrapeObservers& observers = {});

}  // namespace figment
