#include "guard/NodeFieldRanges.h"

#include <Inventor/nodes/SoTextureUnit.h>

#include "guard/NodeLinks.h"

namespace figment::guard {

namespace {

std::string outOfRange(const SoNode& node) {
  if (node.isOfType(SoTextureUnit::getClassTypeId())) {
    const int unit = static_cast<const SoTextureUnit&>(node).unit.getValue();
    if (unit < 0 || unit >= kTextureUnits)
      return describeNode(node) + ": unit = " + std::to_string(unit) + " is not a texture unit: 0 to " +
             std::to_string(kTextureUnits - 1);
  }
  return "";
}

}  // namespace

std::string firstFieldOutOfRange(const SoNode* root) {
  return firstProblemAmongLinkedNodes(root, outOfRange);
}

}  // namespace figment::guard
