#include "nodes/body/HumanBody.h"

#include <Inventor/SoInput.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/errors/SoReadError.h>
#include <Inventor/fields/SoField.h>
#include <Inventor/misc/SoChildList.h>
#include <Inventor/misc/SoNotification.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoShapeHints.h>

#include <algorithm>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "io/MakeHumanLibrary.h"
#include "io/MakeHumanRig.h"
#include "nodes/MeshFields.h"
#include "nodes/NodeSource.h"
#include "sim/body/BaseLayer.h"
#include "sim/body/MeasuredBody.h"
#include "sim/body/PosePresets.h"
#include "sim/body/RigSkin.h"
#include "sim/body/SkinParts.h"
#include "sim/collision/MovingMeshCollider.h"

// The rest body and the pose it turns into, kept for the moving collider's shapes.
struct PoseMotion {
  std::shared_ptr<const figment::HumanRig> rig;
  std::shared_ptr<const figment::RigSkin> skin;
  std::vector<figment::PlacedBone> placed;
  figment::RigPose pose;
  figment::TriangleMesh rest;
  figment::SkinningMethod method = figment::SkinningMethod::DualQuaternion;
  double duration = 0.0;

  std::vector<figment::Vec3> shapeAt(double share) const {
    return figment::skinVertices(*skin, figment::boneTransforms(*rig, placed, pose.partway(share)), rest.vertices,
                                 method);
  }
};

struct HumanBody::Data {
  ~Data() {
    if (material) material->unref();
    if (layerRoot) layerRoot->unref();
  }
  // MakeHuman's rig and the skin bound to it, read once.
  void readRig() {
    if (rig) return;
    const figment::HumanModel& model = human.model();
    rig = std::make_shared<const figment::HumanRig>(figment::readHumanRig(human.dir(), model.base().fileVertexCount));
    skin = std::make_shared<const figment::RigSkin>(figment::bindSkin(*rig, model.base().fileIndex));
  }
  figment::MakeHumanLibrary human;               // this node's: the targets it blends, read once
  std::shared_ptr<const figment::HumanRig> rig;  // read on the first pose
  std::shared_ptr<const figment::RigSkin> skin;
  std::shared_ptr<const PoseMotion> motion;  // null: the rest pose
  mutable std::shared_ptr<const figment::MovingMeshCollider> moving;
  SoMaterial* material = nullptr;  // the skin tone's, in the hidden mesh when set
  // The base layer: the skin's parts (of the base mesh, read with the rig), the layer cut
  // for this body (once), and the separator that draws it, in the hidden mesh while
  // baseLayer is UNDERWEAR.
  std::vector<int> parts;
  std::optional<figment::TriangleMesh> layer;
  SoSeparator* layerRoot = nullptr;
};

FIGMENT_DERIVED_NODE_SOURCE(HumanBody, MeshFile)

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
  SO_NODE_ADD_FIELD(pose, (A_POSE));
  SO_NODE_ADD_EMPTY_MFIELD(rotatedJoints);
  SO_NODE_ADD_EMPTY_MFIELD(rotations);
  SO_NODE_ADD_FIELD(skinning, (DUAL_QUATERNION));
  SO_NODE_ADD_FIELD(poseTime, (0.0f));
  SO_NODE_ADD_FIELD(skinTone, (0));
  SO_NODE_ADD_FIELD(baseLayer, (NONE));
  SO_NODE_ADD_FIELD(baseLayerColor, (0.3f, 0.3f, 0.32f));
  SO_NODE_DEFINE_ENUM_VALUE(BaseLayer, NONE);
  SO_NODE_DEFINE_ENUM_VALUE(BaseLayer, UNDERWEAR);
  SO_NODE_SET_SF_ENUM_TYPE(baseLayer, BaseLayer);
  SO_NODE_DEFINE_ENUM_VALUE(Pose, A_POSE);
  SO_NODE_DEFINE_ENUM_VALUE(Pose, ARMS_DOWN);
  SO_NODE_DEFINE_ENUM_VALUE(Pose, ARM_RAISED);
  SO_NODE_DEFINE_ENUM_VALUE(Pose, WALKING_STEP);
  SO_NODE_DEFINE_ENUM_VALUE(Pose, SITTING);
  SO_NODE_SET_SF_ENUM_TYPE(pose, Pose);
  SO_NODE_DEFINE_ENUM_VALUE(Skinning, LINEAR_BLEND);
  SO_NODE_DEFINE_ENUM_VALUE(Skinning, DUAL_QUATERNION);
  SO_NODE_SET_SF_ENUM_TYPE(skinning, Skinning);
}

HumanBody::~HumanBody() = default;

bool HumanBody::isLoadOption(const SoField* field) const {
  for (const SoSFFloat* own : {&gender, &age, &muscle, &weight, &height, &proportions, &cupSize, &stature, &bustGirth,
                               &underbustGirth, &waistGirth, &hipGirth, &neckGirth, &upperArmGirth, &thighGirth})
    if (field == own) return true;
  for (const SoField* own :
       std::initializer_list<const SoField*>{&pose, &rotatedJoints, &rotations, &skinning, &poseTime, &skinTone})
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
    const figment::HumanModel& model = data_->human.model();
    if (skinTone.getValue() < 0 || skinTone.getValue() > 10)
      throw std::invalid_argument("skinTone " + std::to_string(skinTone.getValue()) + " is not 0 (none) or 1 to 10");
    if (!(poseTime.getValue() >= 0.0f))
      throw std::invalid_argument("poseTime " + std::to_string(poseTime.getValue()) + " must be >= 0");
    const std::vector<figment::MeasurementGoal> goals = goalsOf(*this);
    figment::HumanParameters parameters = parametersOf(*this);
    figment::TriangleMesh body;
    data_->layer.reset();
    if (goals.empty()) {
      body = model.make(parameters);
    } else {
      figment::MeasuredBody made = data_->human.measuredBody(parameters, goals);
      body = std::move(made.body);
      parameters = made.parameters;
    }
    body = posed(parameters, std::move(body));
    setMesh(body, body);
    colourSkin();
    dressBaseLayer();
    return true;
  } catch (const std::exception& e) {
    error = e.what();
  }
  data_->motion.reset();
  data_->moving.reset();
  data_->layer.reset();
  clearMesh();
  dressBaseLayer();
  const SbName name = getName();
  const std::string message =
      std::string("HumanBody") + (name.getLength() ? " '" + std::string(name.getString()) + "'" : "") + ": " + error;
  if (in)
    SoReadError::post(in, "%s", message.c_str());
  else
    SoDebugError::post("HumanBody::load", "%s", message.c_str());
  return false;
}

namespace {

figment::RigPose poseOf(const HumanBody& node, const figment::HumanRig& rig,
                        const std::vector<figment::PlacedBone>& placed) {
  figment::RigPose pose = figment::presetPose(static_cast<figment::PosePreset>(node.pose.getValue()), rig, placed);
  if (node.rotatedJoints.getNum() != node.rotations.getNum())
    throw std::invalid_argument("rotatedJoints has " + std::to_string(node.rotatedJoints.getNum()) +
                                " names but rotations " + std::to_string(node.rotations.getNum()) + " rotations");
  for (int k = 0; k < node.rotatedJoints.getNum(); ++k) {
    const std::string name = node.rotatedJoints[k].getString();
    const int b = rig.find(name);
    if (b < 0) throw std::invalid_argument("rotatedJoints: no bone '" + name + "' in MakeHuman's rig");
    float q[4];
    node.rotations[k].getValue(q[0], q[1], q[2], q[3]);
    pose.set(b, Eigen::Quaterniond(q[3], q[0], q[1], q[2]).normalized() * pose.of(b));
  }
  return pose;
}

}  // namespace

// The rest body turned into the fields' pose; the rest body itself in the rest pose.
figment::TriangleMesh HumanBody::posed(const figment::HumanParameters& parameters, figment::TriangleMesh rest) {
  data_->motion.reset();
  data_->moving.reset();
  if (pose.getValue() == A_POSE && rotatedJoints.getNum() == 0 && rotations.getNum() == 0) return rest;
  data_->readRig();
  auto motion = std::make_shared<PoseMotion>();
  motion->rig = data_->rig;
  motion->skin = data_->skin;
  motion->placed = data_->rig->place(data_->human.model().fileVertices(parameters));
  motion->pose = poseOf(*this, *data_->rig, motion->placed);
  motion->method = skinning.getValue() == LINEAR_BLEND ? figment::SkinningMethod::LinearBlend
                                                       : figment::SkinningMethod::DualQuaternion;
  motion->duration = poseTime.getValue();
  motion->rest = std::move(rest);
  figment::TriangleMesh body = motion->rest;
  body.vertices = motion->shapeAt(1.0);
  data_->motion = std::move(motion);
  return body;
}

SbColor HumanBody::monkSkinTone(int tone) {
  // The Monk Skin Tone scale (skintone.google), tones 1 to 10.
  static constexpr unsigned kTones[10] = {0xf6ede4, 0xf3e7db, 0xf7ead0, 0xeadaba, 0xd7bd96,
                                          0xa07e56, 0x825c43, 0x604134, 0x3a312a, 0x292420};
  const unsigned rgb = kTones[std::clamp(tone, 1, 10) - 1];
  return SbColor(((rgb >> 16) & 0xff) / 255.0f, ((rgb >> 8) & 0xff) / 255.0f, (rgb & 0xff) / 255.0f);
}

// The tone's material first in the hidden mesh (so the drawn body takes it), or none.
void HumanBody::colourSkin() {
  auto* root = static_cast<SoSeparator*>((*getChildren())[0]);
  if (data_->material && root->findChild(data_->material) >= 0) root->removeChild(data_->material);
  if (skinTone.getValue() == 0) return;
  if (!data_->material) {
    data_->material = new SoMaterial;
    data_->material->ref();
  }
  data_->material->diffuseColor = monkSkinTone(skinTone.getValue());
  data_->material->specularColor = SbColor(0.1f, 0.1f, 0.1f);
  data_->material->shininess = 0.2f;
  root->insertChild(data_->material, 0);
}

figment::TriangleMesh HumanBody::restSurface() const {
  return data_->motion ? data_->motion->rest : collisionSurface();
}

std::shared_ptr<const figment::Collider> HumanBody::bodyCollider() const {
  if (!data_->motion) return inherited::bodyCollider();
  if (!data_->moving) {
    std::shared_ptr<const PoseMotion> motion = data_->motion;
    data_->moving = std::make_shared<const figment::MovingMeshCollider>(
        motion->rest.triangles, [motion](double share) { return motion->shapeAt(share); }, motion->duration);
  }
  return data_->moving;
}

void HumanBody::notify(SoNotList* list) {
  inherited::notify(list);
  const SoField* field = list->getLastField();
  if (field == &baseLayer || field == &baseLayerColor) dressBaseLayer();
}

void HumanBody::copyContents(const SoFieldContainer* from, SbBool copyConnections) {
  inherited::copyContents(from, copyConnections);
  // The fields came before the mesh (MeshFile copies it last), so the layer was not drawn:
  // the source's, cut for the same mesh, drawn now.
  data_->layer = static_cast<const HumanBody*>(from)->data_->layer;
  dressBaseLayer();
}

figment::TriangleMesh HumanBody::baseLayerSurface() const {
  if (baseLayer.getValue() == NONE || !data_->layer) return {};
  return *data_->layer;
}

namespace {

// The layer cut for `body` (the class comment): measured on the rest body, drawn posed.
figment::TriangleMesh cutLayer(const figment::TriangleMesh& rest, const figment::TriangleMesh& posed,
                               const std::vector<int>& parts, bool women) {
  figment::BaseLayerShape shape;
  shape.top = women;
  const figment::BaseLayerBounds bounds =
      figment::baseLayerBounds(rest, parts, figment::measureBody(rest).landmarks, shape);
  return figment::cutBaseLayer(rest, posed, parts, bounds, shape);
}

SoSeparator* layerNodes(const figment::TriangleMesh& layer, const SbColor& colour) {
  auto* root = new SoSeparator;
  auto* material = new SoMaterial;
  material->diffuseColor = colour;
  material->specularColor = SbColor(0.15f, 0.15f, 0.15f);
  material->shininess = 0.3f;
  root->addChild(material);
  auto* hints = new SoShapeHints;  // an open surface seen from outside, smooth across its triangles
  hints->vertexOrdering = SoShapeHints::COUNTERCLOCKWISE;
  hints->creaseAngle = 1.0f;
  root->addChild(hints);
  auto* coordinates = new SoCoordinate3;
  auto* faces = new SoIndexedFaceSet;
  figment::setMeshFields(layer, coordinates->point, faces->coordIndex);
  root->addChild(coordinates);
  root->addChild(faces);
  return root;
}

}  // namespace

// Draws the base layer in the hidden mesh (after the skin), or takes it out; cuts it once
// per made body. A layer that cannot be cut is said, and not drawn.
void HumanBody::dressBaseLayer() {
  auto* root = static_cast<SoSeparator*>((*getChildren())[0]);
  if (data_->layerRoot) {
    if (root->findChild(data_->layerRoot) >= 0) root->removeChild(data_->layerRoot);
    data_->layerRoot->unref();
    data_->layerRoot = nullptr;
  }
  if (baseLayer.getValue() == NONE || point.getNum() == 0) return;
  try {
    if (!data_->layer) {
      data_->readRig();
      if (data_->parts.empty()) data_->parts = figment::skinTriangleParts(*data_->rig, data_->human.model().base());
      data_->layer = cutLayer(restSurface(), collisionSurface(), data_->parts, gender.getValue() < 0.5f);
    }
  } catch (const std::exception& e) {
    const SbName name = getName();
    SoDebugError::post("HumanBody::baseLayer", "HumanBody%s: no base layer: %s",
                       name.getLength() ? (" '" + std::string(name.getString()) + "'").c_str() : "", e.what());
    return;
  }
  data_->layerRoot = layerNodes(*data_->layer, baseLayerColor.getValue());
  data_->layerRoot->ref();
  root->addChild(data_->layerRoot);
}
