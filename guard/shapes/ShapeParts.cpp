#include "guard/shapes/ShapeParts.h"

#include <Inventor/nodes/SoFaceSet.h>
#include <Inventor/nodes/SoIndexedLineSet.h>
#include <Inventor/nodes/SoIndexedPointSet.h>
#include <Inventor/nodes/SoIndexedShape.h>
#include <Inventor/nodes/SoIndexedTriangleStripSet.h>
#include <Inventor/nodes/SoLineSet.h>
#include <Inventor/nodes/SoNonIndexedShape.h>
#include <Inventor/nodes/SoPointSet.h>
#include <Inventor/nodes/SoQuadMesh.h>
#include <Inventor/nodes/SoTriangleStripSet.h>

#include <algorithm>
#include <vector>

#include "guard/CoordIndexFaces.h"

namespace figment::guard::shapes {

namespace {

enum class Runs { kFaces, kLines, kStrips, kPoints };

// Parts and faces of runs of `lengths` vertices each.
ShapeParts fromRuns(const std::vector<std::int64_t>& lengths, Runs runs) {
  ShapeParts out;
  for (const std::int64_t n : lengths) {
    out.vertices += n;
    switch (runs) {
      case Runs::kFaces:
        out.parts += 1, out.faces += 1;
        break;
      case Runs::kLines:
        out.parts += std::max<std::int64_t>(n - 1, 0), out.faces += 1;
        break;
      case Runs::kStrips:
        out.parts += 1, out.faces += std::max<std::int64_t>(n - 2, 0);
        break;
      case Runs::kPoints:
        out.parts += n, out.faces += n;
        break;
    }
  }
  return out;
}

// The run lengths of a numVertices field, a -1 taking the rest of the coordinates.
std::vector<std::int64_t> runLengths(const SoMFInt32& numVertices, std::int64_t available) {
  std::vector<std::int64_t> lengths;
  for (int i = 0; i < numVertices.getNum(); ++i) {
    const std::int64_t n = numVertices[i] == -1 ? available : std::max<std::int64_t>(numVertices[i], 0);
    lengths.push_back(n);
    available = std::max<std::int64_t>(available - n, 0);
  }
  return lengths;
}

}  // namespace

ShapeParts indexedShapeParts(const SoIndexedShape& shape) {
  std::vector<std::int64_t> lengths;
  for (const CoordIndexFace& run : coordIndexFaces(shape.coordIndex.getValues(0), shape.coordIndex.getNum()))
    if (run.corners() > 0) lengths.push_back(run.corners());
  if (shape.isOfType(SoIndexedLineSet::getClassTypeId())) return fromRuns(lengths, Runs::kLines);
  if (shape.isOfType(SoIndexedTriangleStripSet::getClassTypeId())) return fromRuns(lengths, Runs::kStrips);
  if (shape.isOfType(SoIndexedPointSet::getClassTypeId())) return fromRuns(lengths, Runs::kPoints);
  return fromRuns(lengths, Runs::kFaces);
}

ShapeParts countedShapeParts(const SoNonIndexedShape& shape, std::int64_t coordinates) {
  const std::int64_t available = std::max<std::int64_t>(coordinates - shape.startIndex.getValue(), 0);
  if (shape.isOfType(SoFaceSet::getClassTypeId()))
    return fromRuns(runLengths(static_cast<const SoFaceSet&>(shape).numVertices, available), Runs::kFaces);
  if (shape.isOfType(SoLineSet::getClassTypeId()))
    return fromRuns(runLengths(static_cast<const SoLineSet&>(shape).numVertices, available), Runs::kLines);
  if (shape.isOfType(SoTriangleStripSet::getClassTypeId()))
    return fromRuns(runLengths(static_cast<const SoTriangleStripSet&>(shape).numVertices, available), Runs::kStrips);
  if (shape.isOfType(SoQuadMesh::getClassTypeId())) {
    const auto& mesh = static_cast<const SoQuadMesh&>(shape);
    const std::int64_t rows = mesh.verticesPerColumn.getValue(), columns = mesh.verticesPerRow.getValue();
    const std::int64_t quadRows = std::max<std::int64_t>(rows - 1, 0);
    return {rows * columns, quadRows, quadRows * std::max<std::int64_t>(columns - 1, 0)};
  }
  if (shape.isOfType(SoPointSet::getClassTypeId())) {
    const std::int64_t count = static_cast<const SoPointSet&>(shape).numPoints.getValue();
    return fromRuns({count == -1 ? available : count}, Runs::kPoints);
  }
  return {};
}

}  // namespace figment::guard::shapes
