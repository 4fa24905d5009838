#pragma once
// The body a garment drapes on, as a drape's plan needs it (sim/drape/DrapePlan.h): its
// collider and its description and, for a jointed body (a Mannequin), the other bodies the
// tradeoff table may pick in its place: its own triangles, or its radial volumes with
// some parts colliding by their triangles. Plain data and functions, no scene graph: a
// node (nodes/cloth/ClothEngineInputs.h) or a program fills it in.

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "sim/collision/Collider.h"

namespace figment {

// What a body is made of: its kind ("mesh", "mannequin", "none") and, by name, how many
// of each kind of part (e.g. "capsule_volumes", "radial_volumes", "exact_parts").
struct BodyDescription {
  std::string kind = "none";
  std::vector<std::pair<std::string, int>> counts;

  int count(const std::string& what) const;  // 0 when it has none
};

struct DrapeBody {
  std::shared_ptr<const Collider> collider;  // null: nothing to collide with
  BodyDescription description;
  // The garments already draped under this one, also in `collider` (a CollisionGroup's
  // layers): a whole-garment drape starts over them (sim/drape/LayerStart.h). Null: none.
  std::shared_ptr<const Collider> beneath;

  // A jointed body's alternatives; `jointed` false: the body is only what `collider` is.
  bool jointed = false;
  // Its own triangles (made when asked: building them costs), and what they are; null
  // when it has no mesh of its own.
  std::function<std::shared_ptr<const Collider>()> triangles;
  BodyDescription trianglesDescription;
  // Its triangles stand for it only in its rest pose and size: "" there, else how it
  // differs ("posed (rotatedJoints), sized (height 0.98)").
  std::string poseOrSize;
  // Its volumes with the parts listed colliding by their own triangles.
  std::function<std::shared_ptr<const Collider>(const std::vector<int>& parts)> withExactParts;
};

}  // namespace figment
