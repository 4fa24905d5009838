#include "guard/shapes/VrmlShapeData.h"

#include <Inventor/VRMLnodes/SoVRMLColor.h>
#include <Inventor/VRMLnodes/SoVRMLCoordinate.h>
#include <Inventor/VRMLnodes/SoVRMLElevationGrid.h>
#include <Inventor/VRMLnodes/SoVRMLIndexedFaceSet.h>
#include <Inventor/VRMLnodes/SoVRMLIndexedLineSet.h>
#include <Inventor/VRMLnodes/SoVRMLNormal.h>
#include <Inventor/VRMLnodes/SoVRMLPointSet.h>
#include <Inventor/VRMLnodes/SoVRMLTextureCoordinate.h>

#include <cstdint>

#include "guard/shapes/IndexProblem.h"

namespace figment::guard::shapes {

namespace {

// The entries of the data node `field` holds (0 for none, or one of another type, which
// viewer/NodeFieldTypes refuses), described for a message.
template <class Data, class Entries>
Indexed dataIn(const SoSFNode& field, Entries Data::*entries, const std::string& noun, const std::string& plural = "") {
  const SoNode* node = field.getValue();
  const int size =
      node && node->isOfType(Data::getClassTypeId()) ? (static_cast<const Data*>(node)->*entries).getNum() : 0;
  const std::string type = node ? node->getTypeId().getName().getString() : "";
  return {size, noun, "the " + type + " has " + counted(size, noun, plural)};
}

Indexed coordinates(const SoSFNode& coord) {
  return dataIn(coord, &SoVRMLCoordinate::point, "point");
}
Indexed colors(const SoSFNode& color) {
  return dataIn(color, &SoVRMLColor::color, "color");
}
Indexed normals(const SoSFNode& normal) {
  return dataIn(normal, &SoVRMLNormal::vector, "normal");
}
Indexed textureCoordinates(const SoSFNode& texCoord) {
  return dataIn(texCoord, &SoVRMLTextureCoordinate::point, "texture coordinate");
}

// Why data go per vertex or per face: "colorPerVertex is TRUE"; texture coordinates always
// go per vertex.
std::string why(const char* perVertexField, bool perVertex) {
  if (!perVertexField) return "texture coordinates go per vertex";
  return std::string(perVertexField) + (perVertex ? " is TRUE" : " is FALSE");
}

// Data the faces or lines of `shape` index, per vertex or per face (per polyline).
std::string perVertexOrFaceProblem(const SoNode& shape, const SoMFInt32& coordIndex, const char* field,
                                   const SoMFInt32& index, const Indexed& data, bool perVertex,
                                   const char* perVertexField, const std::string& faceNoun) {
  if (data.size == 0) return "";  // none: Coin draws without
  const int faces = faceCount(coordIndex);
  const std::string along = perVertex ? "the " + counted(coordIndex.getNum(), "entry", "entries") + " of coordIndex"
                                      : counted(faces, faceNoun);
  if (given(index)) {
    std::string problem = indexProblem(shape, field, index, data);
    if (problem.empty())
      problem = shortIndexProblem(shape, field, index, perVertex ? coordIndex.getNum() : faces, along);
    return problem;
  }
  if (perVertex) {
    Indexed viaCoordIndex = data;
    viaCoordIndex.has +=
        ", and coordIndex indexes them as " + why(perVertexField, true) + " and " + field + " is empty";
    return indexProblem(shape, "coordIndex", coordIndex, viaCoordIndex);
  }
  if (faces > data.size)
    return nodeLabel(shape) + ": " + data.has + " for " + counted(faces, faceNoun) + " (" + why(perVertexField, false) +
           " and " + field + " is empty)";
  return "";
}

std::string faceSetProblem(const SoVRMLIndexedFaceSet& set) {
  if (!set.coord.getValue()) return "";  // Coin draws nothing
  std::string problem = indexProblem(set, "coordIndex", set.coordIndex, coordinates(set.coord));
  if (problem.empty())
    problem = perVertexOrFaceProblem(set, set.coordIndex, "colorIndex", set.colorIndex, colors(set.color),
                                     set.colorPerVertex.getValue(), "colorPerVertex", "face");
  if (problem.empty())
    problem = perVertexOrFaceProblem(set, set.coordIndex, "normalIndex", set.normalIndex, normals(set.normal),
                                     set.normalPerVertex.getValue(), "normalPerVertex", "face");
  if (problem.empty())
    problem = perVertexOrFaceProblem(set, set.coordIndex, "texCoordIndex", set.texCoordIndex,
                                     textureCoordinates(set.texCoord), true, nullptr, "face");
  return problem;
}

std::string lineSetProblem(const SoVRMLIndexedLineSet& set) {
  if (!set.coord.getValue()) return "";
  std::string problem = indexProblem(set, "coordIndex", set.coordIndex, coordinates(set.coord));
  if (problem.empty())
    problem = perVertexOrFaceProblem(set, set.coordIndex, "colorIndex", set.colorIndex, colors(set.color),
                                     set.colorPerVertex.getValue(), "colorPerVertex", "polyline");
  return problem;
}

std::string pointSetProblem(const SoVRMLPointSet& set) {
  const Indexed points = coordinates(set.coord), pointColors = colors(set.color);
  if (pointColors.size == 0 || pointColors.size >= points.size) return "";
  return nodeLabel(set) + ": " + pointColors.has + " for " + counted(points.size, "point") + ": one for each";
}

std::string elevationGridProblem(const SoVRMLElevationGrid& grid) {
  const std::int64_t x = grid.xDimension.getValue(), z = grid.zDimension.getValue();
  const std::string label = nodeLabel(grid);
  if (x < 0 || z < 0)
    return label + ": xDimension " + std::to_string(x) + " and zDimension " + std::to_string(z) +
           " must not be negative";
  const std::int64_t vertices = x * z, quads = x > 1 && z > 1 ? (x - 1) * (z - 1) : 0;
  const std::string ofItsGrid = " of its " + std::to_string(x) + " x " + std::to_string(z) + " grid";
  if (grid.height.getNum() < vertices)
    return label + ": height has " + counted(grid.height.getNum(), "value") + " for the " +
           counted(vertices, "vertex", "vertices") + ofItsGrid;
  const auto enough = [&](const Indexed& data, bool perVertex, const char* perVertexField) -> std::string {
    const std::int64_t needed = perVertex ? vertices : quads;
    if (data.size == 0 || data.size >= needed) return "";
    return label + ": " + data.has + " for the " +
           (perVertex ? counted(needed, "vertex", "vertices") : counted(needed, "quad")) + ofItsGrid + " (" +
           why(perVertexField, perVertex) + ")";
  };
  std::string problem = enough(colors(grid.color), grid.colorPerVertex.getValue(), "colorPerVertex");
  if (problem.empty()) problem = enough(normals(grid.normal), grid.normalPerVertex.getValue(), "normalPerVertex");
  if (problem.empty()) problem = enough(textureCoordinates(grid.texCoord), true, nullptr);
  return problem;
}

}  // namespace

std::string vrmlShapeProblem(const SoVRMLGeometry& shape) {
  if (shape.isOfType(SoVRMLIndexedFaceSet::getClassTypeId()))
    return faceSetProblem(static_cast<const SoVRMLIndexedFaceSet&>(shape));
  if (shape.isOfType(SoVRMLIndexedLineSet::getClassTypeId()))
    return lineSetProblem(static_cast<const SoVRMLIndexedLineSet&>(shape));
  if (shape.isOfType(SoVRMLPointSet::getClassTypeId()))
    return pointSetProblem(static_cast<const SoVRMLPointSet&>(shape));
  if (shape.isOfType(SoVRMLElevationGrid::getClassTypeId()))
    return elevationGridProblem(static_cast<const SoVRMLElevationGrid&>(shape));
  return "";
}

}  // namespace figment::guard::shapes
