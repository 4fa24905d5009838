#pragma once
// A drape with a tolerance: the fastest configuration of the tradeoff table
// (sim/drape/MethodTable.h) measured within it that the body allows, and the body it then
// collides with: a jointed body's own triangles for "triangles" (in its rest pose and size
// only); its radial volumes for "volumes", its capsules for "capsules" (when its volumes are
// all of that kind); for "mix", its radial volumes with the parts the garment starts near
// colliding by their own triangles, in any pose. Configurations of another garment
// resolution are not used (a drape's output is per rest point).

#include <memory>
#include <string>
#include <vector>

#include "sim/drape/DrapeBody.h"
#include "sim/drape/MethodTable.h"

namespace figment {

// The share of a garment's sections the study's progressive drapes begin from.
constexpr double kStudyCoarseShare = 0.25;

// The per-part mix ("mix"): the parts whose volumes come within kExactPartReach of the
// garment's starting nodes collide with their triangles. A garment starts placed about
// the body where it will rest (paper §3.3), so those are the parts it rests on. None
// when `volumes` is not a set of volumes (sim/collision/VolumeSetCollider.h).
constexpr double kExactPartReach = 0.02;  // m
std::vector<int> partsWhereGarmentMeets(const Collider& volumes, const std::vector<Vec3>& garmentStart);

struct MethodChoice {
  MeasuredConfiguration picked;
  std::shared_ptr<const Collider> body;  // what the garment collides with
  BodyDescription bodyDescription;       // and what that is
  // The faster configurations within the tolerance this body cannot use, fastest first,
  // each with why ("implicit:0.02, triangles, progressive off (the Mannequin's triangles
  // are its rest pose and size, and it is posed (rotatedJoints))"), "; " between; "" when none.
  std::string passedOver;
};

// "" when `body` allows `c`; else why not, as a phrase.
std::string whyUnusable(const DrapeBody& body, const MeasuredConfiguration& c);

// Throws std::runtime_error naming the tolerance and the table (no configuration within
// it, and why each within it cannot be used) when there is none to use. `garmentStart` is
// where the garment's nodes start.
MethodChoice chooseMethod(const MethodTable& table, double tolerance, const DrapeBody& body,
                          const std::vector<Vec3>& garmentStart);

}  // namespace figment
