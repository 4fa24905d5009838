#include "guard/shapes/InventorShapeData.h"

#include <Inventor/elements/SoCoordinateElement.h>
#include <Inventor/elements/SoLazyElement.h>
#include <Inventor/elements/SoMaterialBindingElement.h>
#include <Inventor/elements/SoMultiTextureEnabledElement.h>
#include <Inventor/elements/SoNormalBindingElement.h>
#include <Inventor/elements/SoNormalElement.h>
#include <Inventor/elements/SoTextureCoordinateBindingElement.h>
#include <Inventor/elements/SoTextureCoordinateElement.h>
#include <Inventor/misc/SoState.h>
#include <Inventor/nodes/SoFaceSet.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoIndexedMarkerSet.h>
#include <Inventor/nodes/SoIndexedShape.h>
#include <Inventor/nodes/SoLineSet.h>
#include <Inventor/nodes/SoMarkerSet.h>
#include <Inventor/nodes/SoNonIndexedShape.h>
#include <Inventor/nodes/SoPointSet.h>
#include <Inventor/nodes/SoQuadMesh.h>
#include <Inventor/nodes/SoTriangleStripSet.h>
#include <Inventor/nodes/SoVertexProperty.h>

#include <cstdint>

#include "guard/shapes/IndexProblem.h"
#include "guard/shapes/ShapeParts.h"

namespace figment::guard::shapes {

namespace {

const SoVertexProperty* vertexProperty(const SoVertexShape& shape) {
  const SoNode* properties = shape.vertexProperty.getValue();
  return properties && properties->isOfType(SoVertexProperty::getClassTypeId())
             ? static_cast<const SoVertexProperty*>(properties)
             : nullptr;
}

int coordinateCount(const SoVertexShape& shape, SoState* state) {
  const SoVertexProperty* own = vertexProperty(shape);
  return own && own->vertex.getNum() > 0 ? own->vertex.getNum() : SoCoordinateElement::getInstance(state)->getNum();
}

// PER_VERTEX for PER_VERTEX_INDEXED, and so on; OVERALL stays.
int plainBinding(int binding) {
  switch (binding) {
    case SoMaterialBindingElement::PER_PART_INDEXED:
      return SoMaterialBindingElement::PER_PART;
    case SoMaterialBindingElement::PER_FACE_INDEXED:
      return SoMaterialBindingElement::PER_FACE;
    case SoMaterialBindingElement::PER_VERTEX_INDEXED:
      return SoMaterialBindingElement::PER_VERTEX;
    default:
      return binding;
  }
}

// Material and normal bindings share their values (SoMaterialBindingElement's).
bool indexedBinding(int binding) {
  return binding == SoMaterialBindingElement::PER_PART_INDEXED ||
         binding == SoMaterialBindingElement::PER_FACE_INDEXED ||
         binding == SoMaterialBindingElement::PER_VERTEX_INDEXED;
}

// Data of one kind a shape indexes, and how.
struct BoundData {
  Indexed indexed;
  int binding;           // a SoMaterialBindingElement::Binding (normal bindings share the values)
  bool byIndex;          // the binding reads the shape's index field
  bool byCoordIndexToo;  // a per-vertex indexed binding with no index field of its own reads coordIndex
};

std::string boundDataProblem(const SoIndexedShape& shape, const char* field, const SoMFInt32& index,
                             const BoundData& data) {
  if (data.indexed.size == 0) return "";  // none: Coin draws without (or makes normals)
  // VRML 1.0 means PER_VERTEX per vertex of the shape: Coin reads such data through coordIndex.
  if (shape.getNodeType() == SoNode::VRML1 && data.binding == SoMaterialBindingElement::PER_VERTEX) {
    Indexed viaCoordIndex = data.indexed;
    viaCoordIndex.has += ", and coordIndex indexes them as a VRML 1.0 binding PER_VERTEX does";
    return indexProblem(shape, "coordIndex", shape.coordIndex, viaCoordIndex);
  }
  if (!data.byIndex) return "";
  if (given(index)) {
    std::string problem = indexProblem(shape, field, index, data.indexed);
    // Read along the vertices or the faces, however long the index is.
    if (problem.empty() && data.binding == SoMaterialBindingElement::PER_VERTEX_INDEXED)
      problem = shortIndexProblem(shape, field, index, shape.coordIndex.getNum(),
                                  "the " + counted(shape.coordIndex.getNum(), "entry", "entries") + " of coordIndex");
    if (problem.empty() && data.binding == SoMaterialBindingElement::PER_FACE_INDEXED &&
        shape.isOfType(SoIndexedFaceSet::getClassTypeId()))
      problem = shortIndexProblem(shape, field, index, faceCount(shape.coordIndex),
                                  counted(faceCount(shape.coordIndex), "face"));
    return problem;
  }
  if (!data.byCoordIndexToo) return "";
  Indexed viaCoordIndex = data.indexed;
  viaCoordIndex.has +=
      ", and coordIndex indexes them as the binding is PER_VERTEX_INDEXED and " + std::string(field) + " is empty";
  return indexProblem(shape, "coordIndex", shape.coordIndex, viaCoordIndex);
}

BoundData materials(const SoVertexShape& shape, SoState* state) {
  const SoVertexProperty* own = vertexProperty(shape);
  const bool owned = own && own->orderedRGBA.getNum() > 0;
  const int size = owned ? own->orderedRGBA.getNum() : SoLazyElement::getInstance(state)->getNumDiffuse();
  const int binding = owned ? own->materialBinding.getValue() : SoMaterialBindingElement::get(state);
  return {{size, "material", (owned ? "the VertexProperty has " : "the shape has ") + counted(size, "material")},
          binding,
          indexedBinding(binding),
          binding == SoMaterialBindingElement::PER_VERTEX_INDEXED};
}

BoundData normals(const SoVertexShape& shape, SoState* state) {
  const SoVertexProperty* own = vertexProperty(shape);
  const bool owned = own && own->normal.getNum() > 0;
  const int size = owned ? own->normal.getNum() : SoNormalElement::getInstance(state)->getNum();
  const int binding = owned ? own->normalBinding.getValue() : SoNormalBindingElement::get(state);
  return {{size, "normal", (owned ? "the VertexProperty has " : "the shape has ") + counted(size, "normal")},
          binding,
          indexedBinding(binding),
          binding == SoNormalBindingElement::PER_VERTEX_INDEXED};
}

// Texture coordinates are read only where a texture is on, and only explicit ones are
// indexed (a TextureCoordinate function or Coin's default makes them).
BoundData textureCoordinates(const SoVertexShape& shape, SoState* state) {
  const bool textured = state->isElementEnabled(SoMultiTextureEnabledElement::getClassStackIndex()) &&
                        SoMultiTextureEnabledElement::get(state, 0);
  const SoVertexProperty* own = vertexProperty(shape);
  const bool owned = own && own->texCoord.getNum() > 0;
  int size = 0;
  if (owned)
    size = own->texCoord.getNum();
  else if (SoTextureCoordinateElement::getType(state) == SoTextureCoordinateElement::EXPLICIT)
    size = SoTextureCoordinateElement::getInstance(state)->getNum();
  const bool indexed =
      SoTextureCoordinateBindingElement::get(state) == SoTextureCoordinateBindingElement::PER_VERTEX_INDEXED;
  // In material-binding terms; without a texture, none are read.
  const int binding = !textured ? int(SoMaterialBindingElement::OVERALL)
                      : indexed ? int(SoMaterialBindingElement::PER_VERTEX_INDEXED)
                                : int(SoMaterialBindingElement::PER_VERTEX);
  return {{size, "texture coordinate",
           (owned ? "the VertexProperty has " : "the shape has ") + counted(size, "texture coordinate")},
          binding,
          textured && indexed,
          textured && indexed};
}

// Data bound PER_VERTEX, PER_PART or PER_FACE, taken one after another (as are PER_PART_INDEXED
// and PER_FACE_INDEXED data without an index of their own): one for each vertex, part or face.
std::string runningDataProblem(const SoVertexShape& shape, const BoundData& data, const ShapeParts& parts,
                               bool ownIndexGiven) {
  if (data.indexed.size == 0) return "";
  std::int64_t needed = 0;
  std::string what, binding;
  switch (data.binding) {
    case SoMaterialBindingElement::PER_VERTEX:
      needed = parts.vertices, what = counted(parts.vertices, "vertex", "vertices"), binding = "PER_VERTEX";
      break;
    case SoMaterialBindingElement::PER_PART_INDEXED:
      if (ownIndexGiven) return "";
      [[fallthrough]];
    case SoMaterialBindingElement::PER_PART:
      needed = parts.parts, what = counted(parts.parts, "part"), binding = "PER_PART";
      break;
    case SoMaterialBindingElement::PER_FACE_INDEXED:
      if (ownIndexGiven) return "";
      [[fallthrough]];
    case SoMaterialBindingElement::PER_FACE:
      needed = parts.faces, what = counted(parts.faces, "face"), binding = "PER_FACE";
      break;
    default:
      return "";
  }
  if (needed <= data.indexed.size) return "";
  return nodeLabel(shape) + ": " + data.indexed.has + " for its " + what + " (bound " + binding + ", one each)";
}

// Markers are Coin's own and those a program adds; NONE (-1) draws none. Coin skips NONE
// only: another negative index reads before its marker list (4000000000, which an int32 holds
// as -294967296, crashed; found by fuzz_scene).
std::string markerProblem(const SoShape& shape, const SoMFInt32& markerIndex) {
  const int markers = SoMarkerSet::getNumDefinedMarkers();
  for (int i = 0; i < markerIndex.getNum(); ++i)
    if (markerIndex[i] >= markers || markerIndex[i] < SoMarkerSet::NONE)
      return nodeLabel(shape) + ": markerIndex[" + std::to_string(i) + "] = " + std::to_string(markerIndex[i]) +
             " is not a marker: there are " + std::to_string(markers) + " (and -1, none)";
  return "";
}

}  // namespace

std::string indexedShapeProblem(const SoIndexedShape& shape, SoState* state) {
  const int points = coordinateCount(shape, state);
  std::string problem = indexProblem(shape, "coordIndex", shape.coordIndex,
                                     {points, "vertex", "the coordinates have " + counted(points, "point")});
  if (problem.empty()) problem = boundDataProblem(shape, "materialIndex", shape.materialIndex, materials(shape, state));
  if (problem.empty()) problem = boundDataProblem(shape, "normalIndex", shape.normalIndex, normals(shape, state));
  if (problem.empty())
    problem = boundDataProblem(shape, "textureCoordIndex", shape.textureCoordIndex, textureCoordinates(shape, state));
  if (problem.empty() && shape.getNodeType() != SoNode::VRML1) {
    const ShapeParts parts = indexedShapeParts(shape);
    problem = runningDataProblem(shape, materials(shape, state), parts, given(shape.materialIndex));
    if (problem.empty()) problem = runningDataProblem(shape, normals(shape, state), parts, given(shape.normalIndex));
    if (problem.empty())
      problem = runningDataProblem(shape, textureCoordinates(shape, state), parts, given(shape.textureCoordIndex));
  }
  if (problem.empty() && shape.isOfType(SoIndexedMarkerSet::getClassTypeId()))
    problem = markerProblem(shape, static_cast<const SoIndexedMarkerSet&>(shape).markerIndex);
  return problem;
}

std::string countedShapeProblem(const SoNonIndexedShape& shape, SoState* state) {
  const std::int64_t points = coordinateCount(shape, state);
  const std::int64_t start = shape.startIndex.getValue();
  const std::string label = nodeLabel(shape);
  if (start < 0 || start > points)
    return label + ": startIndex = " + std::to_string(start) + " is not a vertex: the coordinates have " +
           counted(points, "point");
  std::int64_t drawn = 0;  // vertices drawn from startIndex
  std::string counts;      // the field(s) that count them
  const auto numVertices = [&](const SoMFInt32& field) -> std::string {
    counts = "numVertices";
    for (int i = 0; i < field.getNum(); ++i) {
      if (field[i] == -1) return "";  // the rest: within the coordinates whatever their number
      if (field[i] < -1)
        return label + ": numVertices[" + std::to_string(i) + "] = " + std::to_string(field[i]) +
               " is neither a count nor the -1 that takes the rest";
      drawn += field[i];
    }
    return "";
  };
  std::string problem;
  if (shape.isOfType(SoFaceSet::getClassTypeId())) {
    problem = numVertices(static_cast<const SoFaceSet&>(shape).numVertices);
  } else if (shape.isOfType(SoLineSet::getClassTypeId())) {
    problem = numVertices(static_cast<const SoLineSet&>(shape).numVertices);
  } else if (shape.isOfType(SoTriangleStripSet::getClassTypeId())) {
    problem = numVertices(static_cast<const SoTriangleStripSet&>(shape).numVertices);
  } else if (shape.isOfType(SoQuadMesh::getClassTypeId())) {
    const auto& mesh = static_cast<const SoQuadMesh&>(shape);
    const std::int64_t rows = mesh.verticesPerColumn.getValue(), columns = mesh.verticesPerRow.getValue();
    counts = "verticesPerRow x verticesPerColumn";
    if (rows < 0 || columns < 0)
      return label + ": verticesPerRow " + std::to_string(columns) + " and verticesPerColumn " + std::to_string(rows) +
             " must not be negative";
    drawn = rows * columns;
  } else if (shape.isOfType(SoPointSet::getClassTypeId())) {
    const std::int64_t count = static_cast<const SoPointSet&>(shape).numPoints.getValue();
    counts = "numPoints";
    if (count < -1)
      return label + ": numPoints = " + std::to_string(count) + " is neither a count nor the -1 that takes the rest";
    drawn = count == -1 ? 0 : count;
  }
  if (problem.empty() && shape.isOfType(SoMarkerSet::getClassTypeId()))
    problem = markerProblem(shape, static_cast<const SoMarkerSet&>(shape).markerIndex);
  if (!problem.empty()) return problem;
  if (start + drawn > points)
    return label + ": " + counts + " draw " + counted(drawn, "vertex", "vertices") + " from startIndex " +
           std::to_string(start) + ": the coordinates have " + counted(points, "point");
  // A shape without indices takes an indexed binding as the plain one (Coin's nonIndexed()).
  const ShapeParts parts = countedShapeParts(shape, points);
  for (BoundData data : {materials(shape, state), normals(shape, state), textureCoordinates(shape, state)}) {
    data.binding = plainBinding(data.binding);
    if (std::string running = runningDataProblem(shape, data, parts, false); !running.empty()) return running;
  }
  return "";
}

}  // namespace figment::guard::shapes
