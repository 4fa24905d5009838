#include "nodes/body/HumanBody.h"

#include <Inventor/SoInput.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/errors/SoReadError.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "io/MakeHumanFiles.h"
#include "io/TargetLibrary.h"
#include "sim/body/BodyFit.h"

SO_NODE_SOURCE(HumanBody);

struct HumanBody::Data {
  std::string dir;
  std::unique_ptr<figment::TargetLibrary> library;
  std::optional<figment::HumanModel> model;
};

void HumanBody::initClass() {
  if (classTypeId != SoType::badType()) return;
  MeshFile::initClass();
  SO_NODE_INIT_CLASS(HumanBody, MeshFile, "MeshFile");
}

HumanBody::HumanBody() : data_(std::make_unique<Data>()) {
  SO_NODE_CONSTRUCTOR(HumanBody);
  SO_NODE_ADD_FIELD(gender, (0.0f));
  SO_NODE_ADD_FIELD(age, (0.5f));
  SO_NODE_ADD_FIELD(muscle, (0.5f));
  SO_NODE_ADD_FIELD(weight, (0.5f));
  SO_NODE_ADD_FIELD(height, (0.5f));
  SO_NODE_ADD_FIELD(proportions, (0.5f));
  SO_NODE_ADD_FIELD(cupSize, (0.5f));
  SO_NODE_ADD_FIELD(stature, (0.0f));
  SO_NODE_ADD_FIELD(bustGirth, (0.0f));
  SO_NODE_ADD_FIELD(underbustGirth, (0.0f));
  SO_NODE_ADD_FIELD(waistGirth, (0.0f));
  SO_NODE_ADD_FIELD(hipGirth, (0.0f));
  SO_NODE_ADD_FIELD(neckGirth, (0.0f));
  SO_NODE_ADD_FIELD(upperArmGirth, (0.0f));
  SO_NODE_ADD_FIELD(thighGirth, (0.0f));
}

HumanBody::~HumanBody() = default;

bool HumanBody::isLoadOption(const SoField* field) const {
  for (const SoSFFloat* own : {&gender, &age, &muscle, &weight, &height, &proportions, &cupSize, &stature, &bustGirth,
                               &underbustGirth, &waistGirth, &hipGirth, &neckGirth, &upperArmGirth, &thighGirth})
    if (field == own) return true;
  return inherited::isLoadOption(field);
}

namespace {

figment::HumanParameters parametersOf(const HumanBody& node) {
  figment::HumanParameters p;
  p.macro.gender = node.gender.getValue();
  p.macro.age = node.age.getValue();
  p.macro.muscle = node.muscle.getValue();
  p.macro.weight = node.weight.getValue();
  p.macro.height = node.height.getValue();
  p.macro.proportions = node.proportions.getValue();
  p.macro.cupSize = node.cupSize.getValue();
  return p;
}

std::vector<figment::MeasurementGoal> goalsOf(const HumanBody& node) {
  const std::pair<const char*, const SoSFFloat*> fields[] = {{"stature", &node.stature},
                                                             {"bust_girth", &node.bustGirth},
                                                             {"underbust_girth", &node.underbustGirth},
                                                             {"waist_girth", &node.waistGirth},
                                                             {"hip_girth", &node.hipGirth},
                                                             {"neck_girth", &node.neckGirth},
                                                             {"upper_arm_girth", &node.upperArmGirth},
                                                             {"thigh_girth", &node.thighGirth}};
  std::vector<figment::MeasurementGoal> goals;
  for (const auto& [key, field] : fields)
    if (field->getValue() != 0) goals.push_back({key, field->getValue()});
  return goals;
}

}  // namespace

bool HumanBody::load(SoInput* in) {
  std::string error;
  try {
    if (fileName.getValue().getLength() != 0)
      throw std::invalid_argument("fileName \"" + std::string(fileName.getValue().getString()) +
                                  "\": a HumanBody makes its mesh; leave fileName empty");
    if (!data_->model) {
      data_->dir = figment::findMakeHumanData();
      if (data_->dir.empty())
        throw std::runtime_error("MakeHuman's data not found: run scripts/setup.sh, or set FIGMENT_MAKEHUMAN_DIR");
      data_->library = std::make_unique<figment::TargetLibrary>(data_->dir);
      data_->model.emplace(figment::loadHumanModel(data_->dir, *data_->library));
    }
    const std::vector<figment::MeasurementGoal> goals = goalsOf(*this);
    const figment::TriangleMesh body = goals.empty() ? data_->model->make(parametersOf(*this))
                                                     : figment::fitBody(*data_->model, parametersOf(*this), goals).body;
    setMesh(body, body);
    return true;
  } catch (const std::exception& e) {
    error = e.what();
  }
  clearMesh();
  const SbName name = getName();
  const std::string message =
      std::string("HumanBody") + (name.getLength() ? " '" + std::string(name.getString()) + "'" : "") + ": " + error;
  if (in)
    SoReadError::post(in, "%s", message.c_str());
  else
    SoDebugError::post("HumanBody::load", "%s", message.c_str());
  return false;
}
