#include "nodes/body/MannequinSkin.h"

#include <Inventor/actions/SoAction.h>
#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/actions/SoGetPrimitiveCountAction.h>
#include <Inventor/actions/SoPickAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/errors/SoReadError.h>
#include <Inventor/misc/SoChildList.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoSeparator.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "nodes/NodeSource.h"
#include "nodes/body/HiddenChildren.h"
#include "nodes/body/Mannequin.h"
#include "sim/body/Skeleton.h"
#include "sim/core/TriangleMesh.h"

struct MannequinSkin::Impl {
  explicit Impl(MannequinSkin* owner) : children(owner) {}
  SoChildList children;  // the hidden mesh
  SoCoordinate3* coordinates = nullptr;
  SoIndexedFaceSet* faces = nullptr;
  bool dirty = true;
  bool updating = false;  // our own changes to the hidden mesh do not make us dirty
  std::string error;
};

FIGMENT_NODE_SOURCE(MannequinSkin, SoNode, "Node")

MannequinSkin::MannequinSkin() : impl_(std::make_unique<Impl>(this)) {
  SO_NODE_CONSTRUCTOR(MannequinSkin);
  SO_NODE_ADD_FIELD(mannequin, (nullptr));
  SO_NODE_ADD_EMPTY_MFIELD(parts);
  const figment::HiddenMesh mesh = figment::appendHiddenMesh(impl_->children);
  impl_->coordinates = mesh.coordinates;
  impl_->faces = mesh.faces;
}

MannequinSkin::~MannequinSkin() {
  impl_->children.truncate(0);
}

const std::string& MannequinSkin::lastError() const {
  return impl_->error;
}

std::string MannequinSkin::label() const {
  const SbName name = getName();
  return std::string("MannequinSkin") + (name.getLength() ? " '" + std::string(name.getString()) + "'" : "") + ": ";
}

std::string MannequinSkin::mannequinTypeError() const {
  const SoNode* node = mannequin.getValue();
  if (!node || node->isOfType(Mannequin::getClassTypeId())) return "";
  return std::string("mannequin is a ") + node->getTypeId().getName().getString() + ", not a Mannequin";
}

// A mannequin of the wrong type is the file's mistake: said where it is read, not left
// to draw nothing in silence.
SbBool MannequinSkin::readInstance(SoInput* in, unsigned short flags) {
  if (!inherited::readInstance(in, flags)) return FALSE;
  const std::string error = mannequinTypeError();
  if (error.empty()) return TRUE;
  SoReadError::post(in, "%s", (label() + error).c_str());  // fails the read; Coin adds file and line
  return FALSE;
}

void MannequinSkin::notify(SoNotList* list) {
  if (impl_ && !impl_->updating) impl_->dirty = true;
  inherited::notify(list);
}

void MannequinSkin::update() {
  if (!impl_->dirty) return;
  impl_->dirty = false;
  impl_->updating = true;
  std::string error;
  std::vector<SbVec3f> points;
  std::vector<int32_t> indices;
  try {
    SoNode* node = mannequin.getValue();
    if (const std::string wrongType = mannequinTypeError(); !wrongType.empty()) throw std::invalid_argument(wrongType);
    if (node) {
      const auto* m = static_cast<const Mannequin*>(node);
      const figment::TriangleMesh& body = m->posedBody();
      const std::vector<int>& owner = m->triangleParts();
      std::vector<bool> wanted(m->skeleton().parts.size(), parts.getNum() == 0);
      for (int i = 0; i < parts.getNum(); ++i) {
        const std::string name = parts[i].getString();
        bool found = false;
        for (size_t k = 0; k < m->skeleton().parts.size(); ++k)
          if (m->skeleton().parts[k].name == name) wanted[k] = found = true;
        if (!found) throw std::invalid_argument("parts[" + std::to_string(i) + "] = \"" + name + "\" is not a part");
      }
      for (const figment::Vec3& v : body.vertices) points.emplace_back(float(v.x()), float(v.y()), float(v.z()));
      for (size_t t = 0; t < body.triangles.size(); ++t)
        if (wanted[owner[t]])
          indices.insert(indices.end(), {body.triangles[t][0], body.triangles[t][1], body.triangles[t][2], -1});
    }
  } catch (const std::exception& e) {
    error = label() + e.what();
    points.clear(), indices.clear();
  }
  if (!error.empty() && error != impl_->error) SoDebugError::post("MannequinSkin", "%s", error.c_str());
  impl_->error = error;
  impl_->coordinates->point.setValues(0, int(points.size()), points.data());
  impl_->coordinates->point.setNum(int(points.size()));
  impl_->faces->coordIndex.setValues(0, int(indices.size()), indices.data());
  impl_->faces->coordIndex.setNum(int(indices.size()));
  impl_->updating = false;
}

SoChildList* MannequinSkin::getChildren() const {
  return &impl_->children;
}

void MannequinSkin::doAction(SoAction* action) {
  update();
  figment::traverseHidden(impl_->children, action);
}

void MannequinSkin::callback(SoCallbackAction* action) {
  MannequinSkin::doAction(action);
}
void MannequinSkin::GLRender(SoGLRenderAction* action) {
  MannequinSkin::doAction(action);
}
void MannequinSkin::getBoundingBox(SoGetBoundingBoxAction* action) {
  MannequinSkin::doAction(action);
}
void MannequinSkin::pick(SoPickAction* action) {
  MannequinSkin::doAction(action);
}
void MannequinSkin::getPrimitiveCount(SoGetPrimitiveCountAction* action) {
  MannequinSkin::doAction(action);
}
void MannequinSkin::search(SoSearchAction* action) {
  SoNode::search(action);
}
