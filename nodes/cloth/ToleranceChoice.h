#pragma once
// ClothEngine.tolerance: the fastest measured configuration within a deviation
// (io/TradeoffTable.h), as the engine can use it: its method onto the parameters, its
// collision body from the engine's body (the Mannequin's own triangles for
// "triangles"; the engine's body itself for "volumes" or "capsules" when its volumes
// are all of that kind), its progressive schedule on a progressive mesh made now, at
// the study's share of the sections. Configurations of another garment resolution are
// not used (the output is per rest point).

#include "io/TradeoffTable.h"
#include "sim/collision/Collider.h"

#include <memory>
#include <string>

class ClothEngine;

namespace figment {

// The table the engine reads: $FIGMENT_TRADEOFF_TABLE, else the installed one, else the
// source tree's docs/tradeoff-table.csv.
std::string tradeoffTablePath();

// The share of a garment's sections the study's progressive drapes begin from.
constexpr double kStudyCoarseShare = 0.25;

struct ToleranceChoice {
  MeasuredConfiguration picked;
  std::shared_ptr<const Collider> body;
};

// Throws std::runtime_error naming the field and value (no configuration within it),
// or the table file, when there is none to use.
ToleranceChoice chooseForTolerance(const ClothEngine& engine, ClothParameters& parameters);

}  // namespace figment
