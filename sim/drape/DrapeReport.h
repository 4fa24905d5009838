#pragma once
// What one drape was and did, in one value: the method that ran and why it was picked,
// the body it collided with, the run (its steps, costs and how it ended), a progressive
// drape's levels and settling, where it came from, and its verdict. Every front end reads
// this one report (ClothEngine::lastRun, the session, figment-view --stats, the service's
// X-Figment-Drape, the bench), and the drape cache keeps it beside the positions
// (io/DrapeRecord.h).

#include <string>

#include "sim/cloth/DrapeResult.h"
#include "sim/drape/DrapeBody.h"
#include "sim/drape/DrapeMethod.h"
#include "sim/progressive/ProgressiveDrape.h"

namespace figment {

struct DrapeReport {
  // The method that ran: the parameters' or, with a tolerance, the picked configuration's;
  // the strain clamping's bound and the run's bound on simulated time (s).
  DrapeMethod method;
  double strainLimit = 0.0, maxTime = 0.0;
  // With a tolerance: the configuration picked (its label; "" without) and its measured
  // worst deviation, % of the garment's height; the body as the study names it
  // (triangles, volumes, capsules or mix); the faster configurations within the tolerance
  // the body could not use, and why ("" when none).
  std::string picked;
  double pickedDeviation = 0.0;
  std::string pickedBody;
  std::string passedOver;
  BodyDescription body;  // what the garment collided with ("none" when nothing)

  int triangles = 0;  // the garment's
  DrapeResult run;
  // Progressive drapes: the level reached, of how many, and its sections; when the end
  // level arrived and how far the garment moved after it.
  int level = 0, levels = 0, sections = 0;
  EndLevelSettling settling;

  // Nodes moved out over the layers beneath before the first step (sim/drape/LayerStart.h):
  // the garment started over the garments under it, not where it was cut. 0: none.
  int startedOverLayers = 0;
  // It started from an earlier drape's shape (another size's, sim/fit/SizeFitter.h), not
  // from the garment's rest shape.
  bool warm = false;
  // The drape came from a drape cache: the report is the run that made it, but
  // wallSeconds, which is then the time to find and read it.
  bool fromCache = false;
  double wallSeconds = 0.0;  // planning, setting up and running it, s

  // The garment checked against its body before the drape, where that may make the drape
  // wrong (nodes starting inside the body, faces wound clockwise); "" when none.
  std::string garmentWarning;
  // verdictOf(*this) once the drape ended: "" when clean.
  std::string verdict;
};

// The report's verdict: the garment's warning and the run's ending (sim/cloth/DrapeVerdict.h),
// "; " between, "" when the drape is clean ("not at rest after maxTime 5 s (max speed
// 0.31 m/s); torn: an edge at 2.02 times its rest length (bound 1.5)").
std::string verdictOf(const DrapeReport& report);

}  // namespace figment
