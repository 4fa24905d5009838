#include "nodes/body/Mannequin.h"

#include <Inventor/SbMatrix.h>
#include <Inventor/SoInput.h>
#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/actions/SoGetPrimitiveCountAction.h>
#include <Inventor/actions/SoPickAction.h>
#include <Inventor/elements/SoDiffuseColorElement.h>
#include <Inventor/elements/SoModelMatrixElement.h>
#include <Inventor/errors/SoReadError.h>
#include <Inventor/misc/SoChildList.h>
#include <Inventor/misc/SoState.h>

#include <algorithm>
#include <stdexcept>

#include "nodes/NodeSource.h"
#include "nodes/body/CapsuleVolume.h"
#include "nodes/body/CollisionVolumeNode.h"
#include "nodes/body/ExactVolume.h"
#include "nodes/body/MeshFile.h"
#include "nodes/body/RadialDepthVolume.h"
#include "nodes/body/SkeletonJoints.h"
#include "sim/body/BodyParts.h"
#include "sim/body/GirthBlend.h"
#include "sim/body/Posing.h"
#include "sim/body/Skinning.h"
#include "sim/collision/CollisionVolume.h"
#include "sim/collision/VolumeSetCollider.h"

struct Mannequin::Model {
  figment::Skeleton skeleton;
  std::vector<VolumeEntry> volumes;
  figment::Pose pose;
  figment::Sizing sizing;
  std::vector<Eigen::Affine3d> transforms;
  std::vector<char> exactPart;  // per skeleton part: named in exactParts
};

FIGMENT_NODE_SOURCE(Mannequin, SoGroup, "Group")

Mannequin::Mannequin() {
  SO_NODE_CONSTRUCTOR(Mannequin);
  SO_NODE_ADD_FIELD(body, (nullptr));
  SO_NODE_ADD_EMPTY_MFIELD(rotatedJoints);
  SO_NODE_ADD_EMPTY_MFIELD(rotations);
  SO_NODE_ADD_FIELD(height, (1.0f));
  SO_NODE_ADD_FIELD(chest, (1.0f));
  SO_NODE_ADD_FIELD(waist, (1.0f));
  SO_NODE_ADD_FIELD(hips, (1.0f));
  SO_NODE_ADD_FIELD(armLength, (1.0f));
  SO_NODE_ADD_FIELD(blendRadius, (0.04f));
  SO_NODE_ADD_EMPTY_MFIELD(exactParts);
  SO_NODE_ADD_FIELD(showVolumes, (FALSE));
  SO_NODE_ADD_FIELD(volumeColor, (0.1f, 0.85f, 0.25f));
}

Mannequin::~Mannequin() = default;

std::string Mannequin::label() const {
  return getName().getLength() > 0 ? "Mannequin '" + std::string(getName().getString()) + "'" : "Mannequin";
}

// --- the model: fields and children -> skeleton, volumes, pose, transforms ----------

namespace {

// Every node below `node` (File contents and inactive Switch children included), not
// below another Mannequin.
template <typename Visit>
void visitBelow(SoNode* node, Visit&& visit) {
  SoChildList* children = node->getChildren();
  if (!children) return;
  for (int i = 0; i < children->getLength(); ++i) {
    SoNode* child = (*children)[i];
    visit(child);
    if (!child->isOfType(Mannequin::getClassTypeId())) visitBelow(child, visit);
  }
}

int partIndex(const figment::Skeleton& skeleton, const std::string& name) {
  for (size_t k = 0; k < skeleton.parts.size(); ++k)
    if (skeleton.parts[k].name == name) return static_cast<int>(k);
  return -1;
}

std::string partNames(const figment::Skeleton& skeleton) {
  std::string names;
  for (const figment::BodyPart& p : skeleton.parts) names += (names.empty() ? "" : ", ") + p.name;
  return names;
}

}  // namespace

const Mannequin::Model& Mannequin::model() const {
  if (model_) return *model_;
  auto model = std::make_shared<Model>();
  auto self = const_cast<Mannequin*>(this);
  try {
    std::vector<SkeletonJoints*> joints;
    std::vector<CollisionVolumeNode*> volumes;
    visitBelow(self, [&](SoNode* n) {
      if (n->isOfType(SkeletonJoints::getClassTypeId())) joints.push_back(static_cast<SkeletonJoints*>(n));
      if (n->isOfType(CollisionVolumeNode::getClassTypeId())) volumes.push_back(static_cast<CollisionVolumeNode*>(n));
    });
    if (joints.size() != 1)
      throw std::invalid_argument("has " + std::to_string(joints.size()) + " SkeletonJoints below it, not 1");
    model->skeleton = joints[0]->skeleton();
    if (volumes.empty())
      throw std::invalid_argument("has no volumes below it (CapsuleVolume, RadialDepthVolume, ExactVolume)");
    for (CollisionVolumeNode* v : volumes) {
      const std::string name = v->part.getValue().getString();
      const int part = partIndex(model->skeleton, name);
      if (part < 0)
        throw std::invalid_argument(v->label() + ": part = \"" + name + "\" is not a part (" +
                                    partNames(model->skeleton) + ")");
      model->volumes.push_back({v, part});
    }

    if (rotatedJoints.getNum() != rotations.getNum())
      throw std::invalid_argument("rotatedJoints has " + std::to_string(rotatedJoints.getNum()) +
                                  " names but rotations has " + std::to_string(rotations.getNum()) + " values");
    model->pose.rotations.assign(model->skeleton.joints.size(), Eigen::Quaterniond::Identity());
    for (int i = 0; i < rotatedJoints.getNum(); ++i) {
      const std::string name = rotatedJoints[i].getString();
      const int j = model->skeleton.joint(name);
      if (j < 0)
        throw std::invalid_argument("rotatedJoints[" + std::to_string(i) + "] = \"" + name + "\" is not a joint");
      SbVec3f axis;
      float angle = 0.0f;
      rotations[i].getValue(axis, angle);
      model->pose.rotations[j] =
          Eigen::Quaterniond(Eigen::AngleAxisd(angle, Eigen::Vector3d(axis[0], axis[1], axis[2]).normalized())) *
          model->pose.rotations[j];
    }
    model->sizing = {height.getValue(), chest.getValue(), waist.getValue(), hips.getValue(), armLength.getValue()};
    if (!(blendRadius.getValue() > 0.0f))
      throw std::invalid_argument("blendRadius = " + std::to_string(blendRadius.getValue()) + " must be > 0");
    model->transforms = figment::partTransforms(model->skeleton, model->pose, model->sizing);
    model->exactPart.assign(model->skeleton.parts.size(), 0);
    for (int i = 0; i < exactParts.getNum(); ++i) {
      const std::string name = exactParts[i].getString();
      const int part = partIndex(model->skeleton, name);
      if (part < 0)
        throw std::invalid_argument("exactParts[" + std::to_string(i) + "] = \"" + name + "\" is not a part (" +
                                    partNames(model->skeleton) + ")");
      model->exactPart[part] = 1;
    }
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(label() + ": " + e.what());
  }
  model_ = std::move(model);
  return *model_;
}

const figment::Skeleton& Mannequin::skeleton() const {
  return model().skeleton;
}
const std::vector<Eigen::Affine3d>& Mannequin::partTransforms() const {
  return model().transforms;
}
const std::vector<Mannequin::VolumeEntry>& Mannequin::volumes() const {
  return model().volumes;
}

namespace {

// Rings of the neighbouring parts' triangles an exact part keeps beyond its cut (about
// 1 cm each on the default body): its surface overlaps the next part's, so a node at the
// seam meets the true surface of one or the other (sim/body/BodyParts.h).
constexpr int kExactBorderRings = 3;

MeshFile* bodyMesh(const SoSFNode& body, const std::string& label) {
  SoNode* node = body.getValue();
  if (!node) return nullptr;
  if (!node->isOfType(MeshFile::getClassTypeId()))
    throw std::invalid_argument(label + ": body is a " + node->getTypeId().getName().getString() + ", not a MeshFile");
  return static_cast<MeshFile*>(node);
}

}  // namespace

std::shared_ptr<const figment::Collider> Mannequin::collider() const {
  if (!collider_) collider_ = buildCollider(model().exactPart);
  return collider_;
}

std::shared_ptr<const figment::Collider> Mannequin::colliderWithExactParts(const std::vector<int>& alsoExact) const {
  std::vector<char> exact = model().exactPart;
  for (int part : alsoExact) {
    if (part < 0 || part >= static_cast<int>(exact.size()))
      throw std::invalid_argument(label() + ": part " + std::to_string(part) + " is not a part of its skeleton");
    exact[part] = 1;
  }
  return buildCollider(exact);
}

namespace {

// The node's volume; a radial depth volume with its cross sections grown where its part
// meets a wider torso part (sim/body/GirthBlend.h: otherwise the wider part's end rim
// stands out of it and cloth resting there never settles).
std::shared_ptr<const figment::CollisionVolume> sizedVolume(const CollisionVolumeNode& node, int part,
                                                            const figment::TriangleMesh& triangles,
                                                            const figment::GirthBlend& girth) {
  if (!node.isOfType(RadialDepthVolume::getClassTypeId())) return node.makeVolume(triangles);
  figment::RadialDepthParameters p = static_cast<const RadialDepthVolume&>(node).parameters();
  const size_t sections = p.coefficients.size();
  const figment::Vec3 axis = p.direction.normalized();
  for (size_t j = 0; sections > 1 && j < sections; ++j) {
    const double s = p.length * static_cast<double>(j) / static_cast<double>(sections - 1);
    const double growth = girth.growth(part, p.base + s * axis);
    if (growth != 1.0)
      for (double& c : p.coefficients[j]) c *= growth;
  }
  return figment::makeVolume(p);
}

}  // namespace

std::shared_ptr<const figment::Collider> Mannequin::buildCollider(const std::vector<char>& exact) const {
  const Model& m = model();
  const auto byTriangles = [&](const VolumeEntry& v) {
    return exact[v.part] || v.node->isOfType(ExactVolume::getClassTypeId());
  };
  // The body's parts, only when a part collides with its triangles.
  const bool anyExact = std::find(exact.begin(), exact.end(), 1) != exact.end();
  std::vector<figment::PartMesh> parts;
  for (const VolumeEntry& v : m.volumes)
    if ((anyExact || byTriangles(v)) && parts.empty()) {
      MeshFile* mesh = bodyMesh(body, label());
      if (!mesh)
        throw std::invalid_argument(label() + ": " + (anyExact ? "exactParts" : v.node->label()) +
                                    " needs the Mannequin's body, which is NULL");
      parts = figment::splitIntoParts(mesh->collisionSurface(), m.skeleton, kExactBorderRings);
    }
  std::vector<figment::PosedCollisionVolume> posed;
  const figment::TriangleMesh none;
  const figment::GirthBlend girth(m.skeleton, m.sizing, blendRadius.getValue());
  for (const VolumeEntry& v : m.volumes) {
    if (exact[v.part]) continue;  // below: its triangles once, however many volumes it has
    const figment::TriangleMesh& triangles = parts.empty() ? none : parts[v.part].mesh;
    posed.push_back({v.part, sizedVolume(*v.node, v.part, triangles, girth), m.transforms[v.part]});
  }
  for (size_t part = 0; part < exact.size(); ++part) {
    if (!exact[part]) continue;
    if (parts[part].mesh.triangles.empty())
      throw std::invalid_argument(label() + ": exactParts: part \"" + m.skeleton.parts[part].name +
                                  "\" has no triangles in the body");
    posed.push_back({static_cast<int>(part), figment::makeVolume(parts[part].mesh), m.transforms[part]});
  }
  return std::make_shared<const figment::VolumeSetCollider>(std::move(posed));
}

figment::CollisionBody::Description Mannequin::describeBody() const {
  int capsules = 0, radial = 0, exact = 0;
  try {
    const std::vector<char>& exactPart = model().exactPart;
    exact = static_cast<int>(std::count(exactPart.begin(), exactPart.end(), 1));
    for (const VolumeEntry& v : volumes()) {
      if (exactPart[v.part]) continue;  // its triangles stand in for its volumes
      capsules += v.node->isOfType(CapsuleVolume::getClassTypeId());
      radial += v.node->isOfType(RadialDepthVolume::getClassTypeId());
      exact += v.node->isOfType(ExactVolume::getClassTypeId());
    }
  } catch (const std::exception&) {
    // An unusable mannequin fails the drape, which is reported before any statistics.
  }
  return {"mannequin", {{"capsule_volumes", capsules}, {"radial_volumes", radial}, {"exact_parts", exact}}};
}

const figment::TriangleMesh& Mannequin::posedBody() const {
  if (posedBody_) return *posedBody_;
  const Model& m = model();
  MeshFile* mesh = bodyMesh(body, label());
  if (!mesh) throw std::invalid_argument(label() + ": body is NULL: there is no mesh to pose");
  auto posed = std::make_unique<figment::TriangleMesh>();
  for (int i = 0; i < mesh->point.getNum(); ++i) {
    const SbVec3f& p = mesh->point[i];
    posed->vertices.emplace_back(p[0], p[1], p[2]);
  }
  for (int i = 0; i + 3 < mesh->coordIndex.getNum() + 1; i += 4)
    posed->triangles.push_back({mesh->coordIndex[i], mesh->coordIndex[i + 1], mesh->coordIndex[i + 2]});
  // The parts as the fit assigned them, so skin and volumes move together.
  triangleParts_ = figment::assignTriangles(*posed, m.skeleton);
  skinWeights_ = std::make_unique<figment::SkinWeights>(figment::skinWeights(
      m.skeleton, posed->vertices, figment::vertexParts(*posed, triangleParts_, m.skeleton.parts.size()),
      blendRadius.getValue()));
  posed->vertices = figment::skin(*skinWeights_, m.transforms, posed->vertices);
  posedBody_ = std::move(posed);
  return *posedBody_;
}

const std::vector<int>& Mannequin::triangleParts() const {
  posedBody();
  return triangleParts_;
}

const figment::SkinWeights& Mannequin::skinWeights() const {
  posedBody();
  return *skinWeights_;
}

void Mannequin::notify(SoNotList* list) {
  // Any change of a field, a child or the body: rebuild on the next use.
  model_.reset();
  collider_.reset();
  posedBody_.reset();
  inherited::notify(list);
}

SbBool Mannequin::readInstance(SoInput* in, unsigned short flags) {
  if (!inherited::readInstance(in, flags)) return FALSE;
  try {
    model();
    for (const VolumeEntry& v : model().volumes)
      if (!v.node->isOfType(ExactVolume::getClassTypeId())) v.node->makeVolume({});
  } catch (const std::exception& e) {  // any, not only bad fields: none escapes a read
    SoReadError::post(in, "%s", e.what());
    return FALSE;
  }
  return TRUE;
}

// --- actions: the volumes, posed, when shown ----------------------------------------

namespace {

SbMatrix toSbMatrix(const Eigen::Affine3d& a) {
  // Inventor multiplies row vectors: its matrix is the transpose of Eigen's.
  const Eigen::Matrix4d m = a.matrix();
  SbMatrix out;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out[r][c] = float(m(c, r));
  return out;
}

}  // namespace

void Mannequin::traverseVolumes(SoAction* action) {
  if (!showVolumes.getValue()) return;
  const Model* m = nullptr;
  try {
    m = &model();
  } catch (const std::exception&) {
    return;  // reported where the mannequin is used (ClothEngine, MannequinSkin)
  }
  SoState* state = action->getState();
  state->push();
  const SbColor colour = volumeColor.getValue();
  if (state->isElementEnabled(SoDiffuseColorElement::getClassStackIndex()))
    SoDiffuseColorElement::set(state, this, 1, &colour);
  for (const VolumeEntry& v : m->volumes) {
    state->push();
    SoModelMatrixElement::mult(state, this, toSbMatrix(m->transforms[v.part]));
    action->traverse(v.node);
    state->pop();
  }
  state->pop();
}

void Mannequin::GLRender(SoGLRenderAction* action) {
  traverseVolumes(action);
}
void Mannequin::getBoundingBox(SoGetBoundingBoxAction* action) {
  traverseVolumes(action);
}
void Mannequin::callback(SoCallbackAction* action) {
  traverseVolumes(action);
}
void Mannequin::pick(SoPickAction* action) {
  traverseVolumes(action);
}
void Mannequin::getPrimitiveCount(SoGetPrimitiveCountAction* action) {
  traverseVolumes(action);
}
void Mannequin::handleEvent(SoHandleEventAction*) {}
void Mannequin::getMatrix(SoGetMatrixAction*) {}
