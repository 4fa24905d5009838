#include "serve/request/MeasuredPoses.h"

namespace figment::serve {

namespace {

const std::vector<MeasuredPose> kPoses = {{"rest", PosePreset::APose},
                                          {"arms-down", PosePreset::ArmsDown},
                                          {"arm-raised", PosePreset::ArmRaised},
                                          {"walking", PosePreset::WalkingStep},
                                          {"sitting", PosePreset::Sitting}};

}  // namespace

const std::vector<MeasuredPose>& MeasuredPoses::all() {
  return kPoses;
}

const MeasuredPose* MeasuredPoses::find(const std::string& name) {
  for (const MeasuredPose& pose : all())
    if (pose.name == name) return &pose;
  return nullptr;
}

std::string MeasuredPoses::names() {
  std::string text;
  for (const MeasuredPose& pose : all()) text += (text.empty() ? "" : ", ") + pose.name;
  return text;
}

}  // namespace figment::serve
