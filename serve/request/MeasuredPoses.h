#pragma once
// The poses a measured body (GET /api/render with `sex`) may take: MakeHuman's rig presets
// (sim/body/PosePresets.h), which the HumanBody takes in a drape by moving from its rest
// pose into it (nodes/body/HumanBody.h). The Mannequin's poses (ShopperChoices: relaxed,
// turn-head) turn its own skeleton's joints, which a HumanBody has not: refused for it.

#include <string>
#include <vector>

#include "sim/body/PosePresets.h"

namespace figment::serve {

struct MeasuredPose {
  std::string name;  // the request's `pose`
  PosePreset preset;
};

class MeasuredPoses {
 public:
  // rest (A_POSE, the body as made), arms-down, arm-raised, walking, sitting.
  static const std::vector<MeasuredPose>& all();
  // Null when unknown.
  static const MeasuredPose* find(const std::string& name);
  // The names, comma separated (a 400's "accepted").
  static std::string names();
};

}  // namespace figment::serve
