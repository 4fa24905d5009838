// The meshes are gathered with one SoCallbackAction (Coin's way of reading what a scene
// draws, with the state in force at each shape: coordinates, model matrix, material,
// shape hints): face sets that draw a drape are read from their coordIndex, so a garment
// keeps one vertex per cloth node; every other shape through its triangle callbacks.

#include "session/SceneExport.h"

#include <Inventor/SbMatrix.h>
#include <Inventor/SoFullPath.h>
#include <Inventor/SoPrimitiveVertex.h>
#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/elements/SoCoordinateElement.h>
#include <Inventor/elements/SoDrawStyleElement.h>
#include <Inventor/elements/SoLazyElement.h>
#include <Inventor/elements/SoModelMatrixElement.h>
#include <Inventor/elements/SoShapeHintsElement.h>
#include <Inventor/engines/SoEngineOutput.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoVertexProperty.h>

#include <array>
#include <map>
#include <set>
#include <stdexcept>

#include "nodes/cloth/ClothEngine.h"
#include "nodes/render/ClothingLayer.h"

namespace figment::session {

namespace {

Vec3 toVec3(const SbVec3f& v) {
  return Vec3(v[0], v[1], v[2]);
}

// The nearest DEF name on the path to the node being traversed, itself first; `fallback`
// when none is named.
std::string nearestName(SoCallbackAction* action, const std::string& fallback) {
  const auto* path = static_cast<const SoFullPath*>(action->getCurPath());
  for (int i = path->getLength() - 1; i >= 0; --i) {
    const SbName name = path->getNode(i)->getName();
    if (name.getLength() > 0) return name.getString();
  }
  return fallback;
}

// The material and shape hints in force, and the facing, for a mesh drawn here.
ColouredMesh styledMesh(SoCallbackAction* action, const std::string& name, int materialIndex) {
  SoState* state = action->getState();
  ColouredMesh part;
  part.name = name;
  const SbColor diffuse = SoLazyElement::getDiffuse(state, materialIndex);
  part.colour = {diffuse[0], diffuse[1], diffuse[2]};
  part.opacity = 1.0f - SoLazyElement::getTransparency(state, materialIndex);
  part.twoSided = SoShapeHintsElement::getShapeType(state) != SoShapeHintsElement::SOLID;
  return part;
}

// A shape drawn as lines or points (an edge overlay, a wireframe) or not at all has no
// surface to export.
bool drawnFilled(SoCallbackAction* action) {
  return SoDrawStyleElement::get(action->getState()) == SoDrawStyleElement::FILLED;
}

bool clockwise(SoCallbackAction* action) {
  return SoShapeHintsElement::getVertexOrdering(action->getState()) == SoShapeHintsElement::CLOCKWISE;
}

// A face set's faces, fanned, as triangles of the coordinates they use (renumbered in
// their order, in world coordinates).
TriangleMesh facesOf(const SoIndexedFaceSet* shape, const SbVec3f* points, int count, const SbMatrix& toWorld,
                     bool flip, const std::string& label) {
  const int32_t* index = shape->coordIndex.getValues(0);
  const int indexCount = shape->coordIndex.getNum();
  std::vector<Triangle> faces;
  for (int start = 0; start < indexCount;) {
    int end = start;
    while (end < indexCount && index[end] >= 0) ++end;
    for (int k = start; k < end; ++k)
      if (index[k] >= count)
        throw std::runtime_error(label + ": coordIndex[" + std::to_string(k) + "] = " + std::to_string(index[k]) +
                                 " past its " + std::to_string(count) + " coordinates");
    for (int k = start + 1; k + 1 < end; ++k)
      faces.push_back(flip ? Triangle{index[start], index[k + 1], index[k]}
                           : Triangle{index[start], index[k], index[k + 1]});
    start = end + 1;
  }
  std::vector<int> number(count, -1);
  for (const Triangle& t : faces)
    for (const int corner : t) number[corner] = 0;
  TriangleMesh mesh;
  for (int i = 0; i < count; ++i) {
    if (number[i] < 0) continue;
    number[i] = static_cast<int>(mesh.vertices.size());
    SbVec3f world;
    toWorld.multVecMatrix(points[i], world);
    mesh.vertices.push_back(toVec3(world));
  }
  for (Triangle t : faces) {
    for (int& corner : t) corner = number[corner];
    mesh.triangles.push_back(t);
  }
  return mesh;
}

// One shape's triangles, vertices shared where position and normal agree.
struct ShapeTriangles {
  ColouredMesh part;
  std::map<std::array<float, 6>, int> vertexNumber;
};

class Gatherer {
 public:
  explicit Gatherer(const ExportContent& content) : content_(content) {}
  std::vector<ColouredMesh> gather(SoNode* scene);

 private:
  static SoCallbackAction::Response atCoordinates(void* self, SoCallbackAction*, const SoNode* node);
  static SoCallbackAction::Response atFaceSet(void* self, SoCallbackAction* action, const SoNode* node);
  static void atTriangle(void* self, SoCallbackAction* action, const SoPrimitiveVertex* a, const SoPrimitiveVertex* b,
                         const SoPrimitiveVertex* c);
  void addCorner(ShapeTriangles& shape, SoCallbackAction* action, const SoPrimitiveVertex* v, Triangle& t, int k);

  ExportContent content_;
  std::set<const SbVec3f*> drapedPoints_;  // the values of Coordinate3 nodes fed by a ClothEngine
  std::vector<ColouredMesh> garments_;
  std::vector<ShapeTriangles> others_;
  std::map<const SoNode*, size_t> otherIndex_;
};

std::vector<ColouredMesh> Gatherer::gather(SoNode* scene) {
  SoCallbackAction action;
  action.addPreCallback(SoCoordinate3::getClassTypeId(), &Gatherer::atCoordinates, this);
  action.addPreCallback(SoIndexedFaceSet::getClassTypeId(), &Gatherer::atFaceSet, this);
  if (content_.body) action.addTriangleCallback(SoShape::getClassTypeId(), &Gatherer::atTriangle, this);
  action.apply(scene);
  std::vector<ColouredMesh> meshes = std::move(garments_);
  for (ShapeTriangles& shape : others_) meshes.push_back(std::move(shape.part));
  return meshes;
}

SoCallbackAction::Response Gatherer::atCoordinates(void* self, SoCallbackAction*, const SoNode* node) {
  const auto* coordinates = static_cast<const SoCoordinate3*>(node);
  SoEngineOutput* output = nullptr;
  if (coordinates->point.getConnectedEngine(output) && output->getContainer() &&
      output->getContainer()->isOfType(ClothEngine::getClassTypeId()))
    static_cast<Gatherer*>(self)->drapedPoints_.insert(coordinates->point.getValues(0));
  return SoCallbackAction::CONTINUE;
}

// A garment is read here and pruned (its triangles are not gathered again); any other
// face set goes on to the triangle callback.
SoCallbackAction::Response Gatherer::atFaceSet(void* self, SoCallbackAction* action, const SoNode* node) {
  auto* gatherer = static_cast<Gatherer*>(self);
  if (!drawnFilled(action)) return SoCallbackAction::PRUNE;
  const auto* shape = static_cast<const SoIndexedFaceSet*>(node);
  const auto* vertices = static_cast<const SoVertexProperty*>(shape->vertexProperty.getValue());
  const SoCoordinateElement* state = SoCoordinateElement::getInstance(action->getState());
  const SbVec3f* points = vertices ? vertices->vertex.getValues(0) : state->getArrayPtr3();
  const int count = vertices ? vertices->vertex.getNum() : state->getNum();
  const bool draped = !vertices && gatherer->drapedPoints_.count(points) > 0;
  if (!draped && !shape->isOfType(ClothingLayer::getClassTypeId())) return SoCallbackAction::CONTINUE;
  if (!points) return SoCallbackAction::PRUNE;  // 4D coordinates: not a drape

  const std::string fallback = "garment-" + std::to_string(gatherer->garments_.size());
  ColouredMesh part = styledMesh(action, nearestName(action, fallback), 0);
  const std::string label = std::string(shape->getTypeId().getName().getString()) + " '" + part.name + "'";
  part.mesh = facesOf(shape, points, count, action->getModelMatrix(), clockwise(action), label);
  if (part.mesh.triangles.empty()) return SoCallbackAction::PRUNE;
  part.normals = vertexNormals(part.mesh);
  gatherer->garments_.push_back(std::move(part));
  return SoCallbackAction::PRUNE;
}

void Gatherer::atTriangle(void* self, SoCallbackAction* action, const SoPrimitiveVertex* a, const SoPrimitiveVertex* b,
                          const SoPrimitiveVertex* c) {
  auto* gatherer = static_cast<Gatherer*>(self);
  if (!drawnFilled(action)) return;
  const SoNode* node = action->getCurPathTail();
  auto [found, added] = gatherer->otherIndex_.try_emplace(node, gatherer->others_.size());
  if (added) {
    const std::string fallback = "body-" + std::to_string(gatherer->others_.size());
    gatherer->others_.push_back({styledMesh(action, nearestName(action, fallback), a->getMaterialIndex()), {}});
  }
  ShapeTriangles& shape = gatherer->others_[found->second];
  const bool flip = clockwise(action);
  Triangle t{};
  gatherer->addCorner(shape, action, a, t, 0);
  gatherer->addCorner(shape, action, flip ? c : b, t, 1);
  gatherer->addCorner(shape, action, flip ? b : c, t, 2);
  if (t[0] != t[1] && t[1] != t[2] && t[2] != t[0]) shape.part.mesh.triangles.push_back(t);
}

void Gatherer::addCorner(ShapeTriangles& shape, SoCallbackAction* action, const SoPrimitiveVertex* v, Triangle& t,
                         int k) {
  const SbMatrix& toWorld = action->getModelMatrix();
  SbVec3f point, normal;
  toWorld.multVecMatrix(v->getPoint(), point);
  toWorld.inverse().transpose().multDirMatrix(v->getNormal(), normal);
  if (normal.normalize() == 0.0f) normal = SbVec3f(0, 1, 0);
  const std::array<float, 6> key{point[0], point[1], point[2], normal[0], normal[1], normal[2]};
  auto [found, added] = shape.vertexNumber.try_emplace(key, static_cast<int>(shape.part.mesh.vertices.size()));
  if (added) {
    shape.part.mesh.vertices.push_back(toVec3(point));
    shape.part.normals.push_back(toVec3(normal));
  }
  t[k] = found->second;
}

}  // namespace

std::vector<ColouredMesh> sceneMeshes(SoNode* scene, const ExportContent& content) {
  return Gatherer(content).gather(scene);
}

std::string exportScene(SoNode* scene, const ExportContent& content, const std::string& path,
                        std::vector<std::string>* written) {
  if (!meshSetFormatOf(path)) return "unknown extension (.glb, .gltf or .obj)";
  try {
    const std::vector<ColouredMesh> meshes = sceneMeshes(scene, content);
    if (meshes.empty()) return "nothing to export: the scene draws no garment";
    exportMeshSet(meshes, path, written);
    return "";
  } catch (const std::runtime_error& error) {
    std::string message = error.what();
    if (message.rfind(path + ": ", 0) == 0) message.erase(0, path.size() + 2);  // the caller names the path
    return message;
  }
}

std::vector<unsigned char> exportGlb(SoNode* scene, const ExportContent& content, std::string& error) {
  try {
    const std::vector<ColouredMesh> meshes = sceneMeshes(scene, content);
    if (meshes.empty()) {
      error = "nothing to export: the scene draws no garment";
      return {};
    }
    error.clear();
    return glbOfMeshSet(meshes);
  } catch (const std::runtime_error& e) {
    error = e.what();
    return {};
  }
}

}  // namespace figment::session
