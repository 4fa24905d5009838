#pragma once
// ClothEngine.tolerance: the fastest measured configuration within a deviation
// (io/TradeoffTable.h), as the engine can use it: its method onto the parameters, its
// collision body from the engine's body (the Mannequin's own triangles for
// "triangles", in its rest pose and size only; the engine's body itself for "volumes" or
// "capsules" when its volumes are all of that kind; for "mix", its radial volumes with
// the parts the garment starts near colliding with their own triangles, in any pose), its progressive schedule on a
// progressive mesh made now, at the study's share of the sections. Configurations of another garment resolution are not
// used (the output is per rest point).

#include <memory>
#include <string>
#include <vector>

#include "io/TradeoffTable.h"
#include "sim/collision/Collider.h"

class ClothEngine;
class Mannequin;

namespace figment {

// The table the engine reads: $FIGMENT_TRADEOFF_TABLE, else the installed one, else the
// source tree's docs/tradeoff-table.csv.
std::string tradeoffTablePath();

// The share of a garment's sections the study's progressive drapes begin from.
constexpr double kStudyCoarseShare = 0.25;

// The per-part mix ("mix"): the parts whose volumes come within kExactPartReach of the
// garment's starting nodes collide with their triangles. A garment starts placed about
// the body where it will rest (paper §3.3), so those are the parts it rests on.
constexpr double kExactPartReach = 0.02;  // m
std::vector<int> partsWhereGarmentMeets(const Mannequin& mannequin, const std::vector<Vec3>& garmentStart);

struct ToleranceChoice {
  MeasuredConfiguration picked;
  std::shared_ptr<const Collider> body;
  // The faster configurations within the tolerance this engine cannot use, fastest
  // first, each with why ("implicit:0.02, triangles, progressive off (the Mannequin's
  // triangles are its rest pose and size, and it is posed (rotatedJoints))"), "; "
  // between; "" when none.
  std::string passedOver;
};

// Throws std::runtime_error naming the field and value (no configuration within it,
// and why each within it cannot be used), or the table file, when there is none to use.
// `garment` is the engine's garment, where it starts.
ToleranceChoice chooseForTolerance(const ClothEngine& engine, const TriangleMesh& garment, ClothParameters& parameters);

}  // namespace figment
