#include "io/MakeHumanSession.h"

#include <stdexcept>

#include "io/MakeHumanFiles.h"
#include "io/TargetLibrary.h"

namespace figment {

MakeHumanSession::MakeHumanSession() = default;

MakeHumanSession::~MakeHumanSession() = default;

const std::string& MakeHumanSession::dir() {
  if (dir_.empty()) dir_ = findMakeHumanData();
  return dir_;
}

const HumanModel& MakeHumanSession::model() {
  if (model_) return *model_;
  if (dir().empty()) throw std::runtime_error(kMakeHumanDataMissing);
  library_ = std::make_unique<TargetLibrary>(dir_);
  model_ = std::make_unique<HumanModel>(loadHumanModel(dir_, *library_));
  return *model_;
}

BodyFitResult MakeHumanSession::fit(const HumanParameters& start, const std::vector<MeasurementGoal>& goals) {
  return fitBody(model(), start, goals);
}

BodyFitResult MakeHumanSession::fit(Sex sex, const std::vector<MeasurementGoal>& goals) {
  return fit(start(sex), goals);
}

BodyFitResult MakeHumanSession::fit(const ChartSize& size) {
  return fit(size.sex, goals(size));
}

HumanParameters MakeHumanSession::start(Sex sex) {
  HumanParameters start;
  start.macro.gender = sex == Sex::Male ? 1.0 : 0.0;
  return start;
}

std::vector<MeasurementGoal> MakeHumanSession::goals(const ChartSize& size) {
  return {{"stature", size.stature}, {"bust_girth", size.bust}, {"waist_girth", size.waist}, {"hip_girth", size.hip}};
}

}  // namespace figment
