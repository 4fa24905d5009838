#include "guard/NodeLinks.h"

#include <Inventor/fields/SoMFNode.h>
#include <Inventor/fields/SoSFNode.h>
#include <Inventor/lists/SoFieldList.h>
#include <Inventor/misc/SoChildList.h>
#include <Inventor/nodes/SoNode.h>

#include <unordered_set>

namespace figment::guard {

std::string describeNode(const SoNode& node) {
  std::string text = node.getTypeId().getName().getString();
  const SbName name = node.getName();
  if (name.getLength() > 0) text += std::string(" '") + name.getString() + "'";
  return text;
}

std::vector<SoField*> nodeFields(const SoNode& node) {
  SoFieldList fields;
  node.getFields(fields);
  std::vector<SoField*> out;
  for (int i = 0; i < fields.getLength(); ++i)
    if (fields[i]->isOfType(SoSFNode::getClassTypeId()) || fields[i]->isOfType(SoMFNode::getClassTypeId()))
      out.push_back(fields[i]);
  return out;
}

std::vector<SoNode*> linkedNodes(const SoNode& node) {
  std::vector<SoNode*> links;
  if (const SoChildList* children = node.getChildren())
    for (int i = 0; i < children->getLength(); ++i) links.push_back((*children)[i]);
  std::unordered_set<const SoNode*> linked(links.begin(), links.end());
  const auto addOnce = [&](SoNode* held) {
    if (held && linked.insert(held).second) links.push_back(held);
  };
  for (SoField* field : nodeFields(node)) {
    if (field->isOfType(SoSFNode::getClassTypeId())) {
      addOnce(static_cast<SoSFNode*>(field)->getValue());
    } else {
      const auto& many = *static_cast<SoMFNode*>(field);
      for (int i = 0; i < many.getNum(); ++i) addOnce(many[i]);
    }
  }
  return links;
}

std::string firstProblemAmongLinkedNodes(const SoNode* root, const std::function<std::string(const SoNode&)>& visit) {
  std::unordered_set<const SoNode*> seen;
  for (std::vector<const SoNode*> next{root}; !next.empty();) {
    const SoNode* node = next.back();
    next.pop_back();
    if (!node || !seen.insert(node).second) continue;
    if (std::string problem = visit(*node); !problem.empty()) return problem;
    const std::vector<SoNode*> links = linkedNodes(*node);
    next.insert(next.end(), links.rbegin(), links.rend());  // the first link next
  }
  return "";
}

}  // namespace figment::guard
