#include "io/MakeHumanLibrary.h"

#include <stdexcept>

#include "io/MakeHumanFiles.h"
#include "io/TargetLibrary.h"

namespace figment {

MakeHumanLibrary::MakeHumanLibrary() = default;

MakeHumanLibrary::~MakeHumanLibrary() = default;

const std::string& MakeHumanLibrary::dir() {
  if (dir_.empty()) dir_ = findMakeHumanData();
  return dir_;
}

const HumanModel& MakeHumanLibrary::model() {
  if (model_) return *model_;
  if (dir().empty()) throw std::runtime_error(kMakeHumanDataMissing);
  library_ = std::make_unique<TargetLibrary>(dir_);
  model_ = std::make_unique<HumanModel>(loadHumanModel(dir_, *library_));
  return *model_;
}

MeasuredBody MakeHumanLibrary::measuredBody(const HumanParameters& start, const std::vector<MeasurementGoal>& goals) {
  return makeMeasuredBody(model(), start, goals);
}

MeasuredBody MakeHumanLibrary::measuredBody(Sex sex, const std::vector<MeasurementGoal>& goals) {
  return measuredBody(start(sex), goals);
}

MeasuredBody MakeHumanLibrary::measuredBody(const ChartSize& size) {
  return measuredBody(size.sex, goals(size));
}

HumanParameters MakeHumanLibrary::start(Sex sex) {
  HumanParameters start;
  start.macro.gender = sex == Sex::Male ? 1.0 : 0.0;
  return start;
}

std::vector<MeasurementGoal> MakeHumanLibrary::goals(const ChartSize& size) {
  return {{"stature", size.stature}, {"bust_girth", size.bust}, {"waist_girth", size.waist}, {"hip_girth", size.hip}};
}

}  // namespace figment
