#include "guard/shapes/IndexProblem.h"

#include <Inventor/fields/SoMFInt32.h>
#include <Inventor/nodes/SoNode.h>

#include "guard/CoordIndexFaces.h"

namespace figment::guard::shapes {

std::string nodeLabel(const SoNode& node) {
  const std::string type = node.getTypeId().getName().getString();
  const SbName name = node.getName();
  return name.getLength() ? type + " '" + name.getString() + "'" : type;
}

std::string counted(std::int64_t count, const std::string& noun, const std::string& plural) {
  return std::to_string(count) + " " + (count == 1 ? noun : plural.empty() ? noun + "s" : plural);
}

bool given(const SoMFInt32& index) {
  return index.getNum() > 0 && index[0] >= 0;
}

std::string indexProblem(const SoNode& node, const std::string& field, const SoMFInt32& index, const Indexed& indexed) {
  for (int i = 0; i < index.getNum(); ++i) {
    const int32_t value = index[i];
    if (value >= -1 && value < indexed.size) continue;
    const std::string entry = nodeLabel(node) + ": " + field + "[" + std::to_string(i) + "] = " + std::to_string(value);
    return value < -1 ? entry + " is neither a " + indexed.noun + " nor the -1 that ends a face"
                      : entry + " is not a " + indexed.noun + ": " + indexed.has;
  }
  return "";
}

std::string shortIndexProblem(const SoNode& node, const std::string& field, const SoMFInt32& index, int needed,
                              const std::string& along) {
  if (index.getNum() >= needed) return "";
  return nodeLabel(node) + ": " + field + " has " + counted(index.getNum(), "entry", "entries") + " for " + along;
}

int faceCount(const SoMFInt32& coordIndex) {
  int faces = 0;
  for (const CoordIndexFace& face : coordIndexFaces(coordIndex.getValues(0), coordIndex.getNum()))
    faces += face.corners() > 0;
  return faces;
}

}  // namespace figment::guard::shapes
