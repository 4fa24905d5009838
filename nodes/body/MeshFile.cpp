#include "nodes/body/MeshFile.h"

#include <Inventor/SoInput.h>
#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/actions/SoGetPrimitiveCountAction.h>
#include <Inventor/actions/SoPickAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/errors/SoReadError.h>
#include <Inventor/lists/SbStringList.h>
#include <Inventor/misc/SoChildList.h>
#include <Inventor/misc/SoNotification.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoSeparator.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "io/MeshImport.h"
#include "nodes/MeshFields.h"
#include "nodes/NodeSource.h"
#include "nodes/SceneFiles.h"
#include "nodes/body/HiddenChildren.h"
#include "nodes/cloth/FieldValues.h"
#include "sim/collision/MeshCollider.h"
#include "sim/core/ParameterChecks.h"

struct MeshFile::Impl {
  explicit Impl(MeshFile* owner) : children(owner) {}

  SoChildList children;  // the one hidden child: the drawn mesh
  SoCoordinate3* coordinates = nullptr;
  SoIndexedFaceSet* faces = nullptr;
  figment::TriangleMesh collisionSurface;
  mutable std::shared_ptr<const figment::MeshCollider> collider;
  // Folders of the .iv file this node was read from, so a fileName set later still
  // resolves next to its scene.
  std::vector<std::string> sceneDirectories;
  // True while fields are set in bulk (reading, copying): load once afterwards.
  bool loadSuppressed = false;
};

namespace {

figment::UpAxis toUpAxis(int value) {
  switch (value) {
    case MeshFile::X:
      return figment::UpAxis::X;
    case MeshFile::Z:
      return figment::UpAxis::Z;
    case MeshFile::NEG_X:
      return figment::UpAxis::NegX;
    case MeshFile::NEG_Y:
      return figment::UpAxis::NegY;
    case MeshFile::NEG_Z:
      return figment::UpAxis::NegZ;
    default:
      return figment::UpAxis::Y;
  }
}

std::vector<std::string> toStrings(const SoMFString& field) {
  std::vector<std::string> out;
  for (int i = 0; i < field.getNum(); ++i) out.emplace_back(field[i].getString());
  return out;
}

std::string quoted(const std::string& s) {
  return "\"" + s + "\"";
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& name : names) out += (out.empty() ? "" : ", ") + name;
  return out;
}

std::string text(const SoSFVec3f& field) {
  const SbVec3f& v = field.getValue();
  return figment::formatNumber(v[0]) + " " + figment::formatNumber(v[1]) + " " + figment::formatNumber(v[2]);
}

// The crop box, or nothing when both corners are left at 0 0 0; throws when set but
// not below cropMax on every axis.
std::optional<figment::Bounds> cropBox(const MeshFile& node) {
  const SbVec3f& low = node.cropMin.getValue();
  const SbVec3f& high = node.cropMax.getValue();
  if (low == SbVec3f(0, 0, 0) && high == SbVec3f(0, 0, 0)) return std::nullopt;
  for (int axis = 0; axis < 3; ++axis)
    if (!(low[axis] < high[axis]))
      throw std::invalid_argument("cropMin = " + text(node.cropMin) + " must be below cropMax = " + text(node.cropMax) +
                                  " on every axis");
  figment::Bounds box;
  box.min = figment::Vec3(low[0], low[1], low[2]);
  box.max = figment::Vec3(high[0], high[1], high[2]);
  return box;
}

// The meshes `node`'s fields ask for, as drawn and for collisions, looking in `dirs`;
// throws naming the field and value that cannot be used.
std::pair<figment::TriangleMesh, figment::TriangleMesh> importMeshes(const MeshFile& node,
                                                                     const std::vector<std::string>& dirs) {
  const std::string name = node.fileName.getValue().getString();
  const double scale = figment::writtenValue(node.metresPerUnit.getValue());
  if (!(scale > 0.0) || !std::isfinite(scale))
    throw std::invalid_argument("metresPerUnit = " + figment::formatNumber(scale) + " must be > 0");
  const std::string path = figment::resolveSceneFile(name, dirs);
  if (path.empty()) throw std::runtime_error("fileName " + quoted(name) + " not found");

  figment::ImportOptions options;
  options.metresPerUnit = scale;
  options.upAxis = toUpAxis(node.upAxis.getValue());
  options.exclude = toStrings(node.exclude);
  figment::ImportedMesh drawn = figment::importMesh(path, options);
  if (drawn.mesh.triangles.empty())
    throw std::runtime_error("fileName " + quoted(name) + ": " + path + " has no triangles");

  const std::optional<figment::Bounds> crop = cropBox(node);
  if (crop) {
    drawn.mesh = figment::croppedToBox(drawn.mesh, *crop);
    if (drawn.mesh.triangles.empty())
      throw std::runtime_error("cropMin " + text(node.cropMin) + ", cropMax " + text(node.cropMax) +
                               ": no triangle of " + path + " has its centre in the box");
  }
  const std::vector<std::string> unseen = toStrings(node.collisionExclude);
  if (unseen.empty()) return {drawn.mesh, drawn.mesh};
  for (const auto& excluded : unseen) {
    if (std::find(drawn.meshNames.begin(), drawn.meshNames.end(), excluded) == drawn.meshNames.end())
      throw std::runtime_error("collisionExclude " + quoted(excluded) + ": no such mesh in " + path +
                               " (meshes: " + joined(drawn.meshNames) + ")");
  }
  // The importer gives one merged mesh, so the collision surface is a second import.
  options.exclude.insert(options.exclude.end(), unseen.begin(), unseen.end());
  figment::TriangleMesh collision = figment::importMesh(path, options).mesh;
  if (crop) collision = figment::croppedToBox(collision, *crop);
  return {std::move(drawn.mesh), std::move(collision)};
}

}  // namespace

FIGMENT_NODE_SOURCE(MeshFile, SoNode, "Node")

MeshFile::MeshFile() : impl_(std::make_unique<Impl>(this)) {
  SO_NODE_CONSTRUCTOR(MeshFile);
  SO_NODE_ADD_FIELD(fileName, (""));
  SO_NODE_ADD_FIELD(metresPerUnit, (1.0f));
  SO_NODE_ADD_FIELD(upAxis, (Y));
  SO_NODE_ADD_EMPTY_MFIELD(exclude);
  SO_NODE_ADD_EMPTY_MFIELD(collisionExclude);
  SO_NODE_ADD_FIELD(cropMin, (0.0f, 0.0f, 0.0f));
  SO_NODE_ADD_FIELD(cropMax, (0.0f, 0.0f, 0.0f));
  SO_NODE_ADD_FIELD(reverseFaces, (FALSE));
  SO_NODE_ADD_EMPTY_MFIELD(point);
  SO_NODE_ADD_EMPTY_MFIELD(coordIndex);
  SO_NODE_DEFINE_ENUM_VALUE(UpAxis, X);
  SO_NODE_DEFINE_ENUM_VALUE(UpAxis, Y);
  SO_NODE_DEFINE_ENUM_VALUE(UpAxis, Z);
  SO_NODE_DEFINE_ENUM_VALUE(UpAxis, NEG_X);
  SO_NODE_DEFINE_ENUM_VALUE(UpAxis, NEG_Y);
  SO_NODE_DEFINE_ENUM_VALUE(UpAxis, NEG_Z);
  SO_NODE_SET_SF_ENUM_TYPE(upAxis, UpAxis);

  const figment::HiddenMesh mesh = figment::appendHiddenMesh(impl_->children);
  impl_->coordinates = mesh.coordinates;
  impl_->faces = mesh.faces;
}

MeshFile::~MeshFile() {
  // Drop the hidden mesh while this node is whole: the child list notifies its parent.
  impl_->children.truncate(0);
}

const figment::TriangleMesh& MeshFile::collisionSurface() const {
  return impl_->collisionSurface;
}

std::shared_ptr<const figment::MeshCollider> MeshFile::collider() const {
  if (!impl_->collider && !impl_->collisionSurface.triangles.empty())
    impl_->collider = std::make_shared<const figment::MeshCollider>(impl_->collisionSurface);
  return impl_->collider;
}

std::shared_ptr<const figment::Collider> MeshFile::bodyCollider() const {
  std::shared_ptr<const figment::MeshCollider> exact = collider();
  if (!exact) {
    const std::string name = getName().getLength() ? " '" + std::string(getName().getString()) + "'" : "";
    throw std::invalid_argument("MeshFile" + name + " has no mesh");
  }
  return exact;
}

figment::CollisionBody::Description MeshFile::describeBody() const {
  return {"mesh", {}};
}

// --- reading the mesh -------------------------------------------------------------

bool MeshFile::isLoadOption(const SoField* field) const {
  return field == &fileName || field == &metresPerUnit || field == &upAxis || field == &exclude ||
         field == &collisionExclude || field == &cropMin || field == &cropMax || field == &reverseFaces;
}

SbBool MeshFile::readInstance(SoInput* in, unsigned short flags) {
  // Coin notifies once per field read; the file is read once, after all of them.
  impl_->loadSuppressed = true;
  const SbBool ok = inherited::readInstance(in, flags);
  impl_->loadSuppressed = false;
  if (!ok) return FALSE;
  impl_->sceneDirectories = figment::sceneSearchDirectories(in);
  return load(in) ? TRUE : FALSE;
}

void MeshFile::notify(SoNotList* list) {
  inherited::notify(list);
  if (impl_ && !impl_->loadSuppressed && isLoadOption(list->getLastField())) load(nullptr);
}

bool MeshFile::load(SoInput* in) {
  std::string error;
  try {
    if (fileName.getValue().getLength() == 0) {
      clearMesh();
      return true;
    }
    auto [drawn, collision] = importMeshes(*this, impl_->sceneDirectories);
    if (reverseFaces.getValue())
      for (figment::TriangleMesh* mesh : {&drawn, &collision})
        for (figment::Triangle& t : mesh->triangles) std::swap(t[1], t[2]);
    setMesh(drawn, collision);
    return true;
  } catch (const std::exception& e) {
    error = e.what();
  } catch (...) {
    error = "unknown error while reading the mesh";
  }
  return failLoad("MeshFile", in, error);
}

bool MeshFile::failLoad(const char* kind, SoInput* in, const std::string& error) {
  clearMesh();
  const SbName name = getName();
  const std::string message =
      std::string(kind) + (name.getLength() ? " '" + std::string(name.getString()) + "'" : "") + ": " + error;
  if (in)
    SoReadError::post(in, "%s", message.c_str());  // fails the read; Coin adds file and line
  else
    SoDebugError::post((std::string(kind) + "::load").c_str(), "%s", message.c_str());
  return false;
}

void MeshFile::setMesh(const figment::TriangleMesh& drawn, const figment::TriangleMesh& collision) {
  figment::setMeshFields(drawn, point, coordIndex);
  // Outputs, not settings: default-flagged fields are left out of written files.
  point.setDefault(TRUE);
  coordIndex.setDefault(TRUE);
  impl_->coordinates->point = point;
  impl_->faces->coordIndex = coordIndex;
  impl_->collisionSurface = collision;
  impl_->collider.reset();
}

void MeshFile::clearMesh() {
  setMesh({}, {});
}

void MeshFile::copyContents(const SoFieldContainer* from, SbBool copyConnections) {
  impl_->loadSuppressed = true;  // take the source's mesh instead of reading the file again
  inherited::copyContents(from, copyConnections);
  impl_->loadSuppressed = false;
  const auto* source = static_cast<const MeshFile*>(from);
  // Coin copies only fields that differ from their defaults; the outputs are flagged
  // default (so they are not written), so they are copied here.
  point = source->point;
  coordIndex = source->coordIndex;
  point.setDefault(TRUE);
  coordIndex.setDefault(TRUE);
  impl_->coordinates->point = point;
  impl_->faces->coordIndex = coordIndex;
  impl_->collisionSurface = source->impl_->collisionSurface;
  impl_->collider = source->impl_->collider;
  impl_->sceneDirectories = source->impl_->sceneDirectories;
}

// --- actions: forwarded to the hidden mesh, as SoFile forwards to its children -----

SoChildList* MeshFile::getChildren() const {
  return &impl_->children;
}

void MeshFile::doAction(SoAction* action) {
  figment::traverseHidden(impl_->children, action);
}

void MeshFile::callback(SoCallbackAction* action) {
  MeshFile::doAction(action);
}

void MeshFile::GLRender(SoGLRenderAction* action) {
  MeshFile::doAction(action);
}

void MeshFile::getBoundingBox(SoGetBoundingBoxAction* action) {
  MeshFile::doAction(action);
}

void MeshFile::pick(SoPickAction* action) {
  MeshFile::doAction(action);
}

void MeshFile::getPrimitiveCount(SoGetPrimitiveCountAction* action) {
  MeshFile::doAction(action);
}

void MeshFile::search(SoSearchAction* action) {
  SoNode::search(action);
}
