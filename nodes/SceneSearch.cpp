#include "nodes/SceneSearch.h"

#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/engines/SoNodeEngine.h>
#include <Inventor/fields/SoMFNode.h>
#include <Inventor/fields/SoSFNode.h>
#include <Inventor/lists/SoFieldList.h>
#include <Inventor/misc/SoChildList.h>
#include <Inventor/nodes/SoNode.h>

#include <set>
#include <unordered_set>

#include "nodes/cloth/ClothEngine.h"

namespace figment {

namespace {

// Walks field connections backwards from every container it is given.
class EngineCollector {
 public:
  std::vector<ClothEngine*> engines;

  void visit(SoFieldContainer* container) {
    if (!container || !seen_.insert(container).second) return;
    if (container->isOfType(ClothEngine::getClassTypeId())) engines.push_back(static_cast<ClothEngine*>(container));
    SoFieldList fields;
    container->getFields(fields);
    for (int i = 0; i < fields.getLength(); ++i) visitField(fields[i]);
  }

 private:
  std::set<SoFieldContainer*> seen_;

  void visitField(SoField* field) {
    SoEngineOutput* output = nullptr;
    if (field->getConnectedEngine(output) && output)
      visit(output->isNodeEngineOutput() ? static_cast<SoFieldContainer*>(output->getNodeContainer())
                                         : static_cast<SoFieldContainer*>(output->getContainer()));
    SoField* master = nullptr;
    if (field->getConnectedField(master) && master) visit(master->getContainer());
    // Nodes held in fields (an IndexedFaceSet's vertexProperty) may be fed by engines too.
    if (field->isOfType(SoSFNode::getClassTypeId())) visit(static_cast<SoSFNode*>(field)->getValue());
    if (field->isOfType(SoMFNode::getClassTypeId())) {
      auto* nodes = static_cast<SoMFNode*>(field);
      for (int i = 0; i < nodes->getNum(); ++i) visit((*nodes)[i]);
    }
  }
};

}  // namespace

SoPathList findAll(SoNode* root, SoType type) {
  SoSearchAction search;
  search.setType(type);
  search.setInterest(SoSearchAction::ALL);
  search.setSearchingAll(TRUE);
  search.apply(root);
  return search.getPaths();
}

SoNode* fullTail(const SoPath* path, int fromTail) {
  // SoPath::getFullLength() is private, but a path's fork with itself is its last node, hidden
  // ones included: findFork() compares the full paths (-1 when empty).
  const int index = path->findFork(path) - fromTail;
  return fromTail >= 0 && index >= 0 ? path->getNode(index) : nullptr;
}

std::vector<ClothEngine*> findClothEngines(SoNode* root) {
  // Each node once, depth first (scene order), every child of every group (a Switch's too).
  // Not a search action for every node: that makes a path for each way to reach a node, and
  // each path audits every node along it, so 65,520 paths through shared groups took 4.9 s
  // (fuzz_scene: 12 s under the sanitizers), growing with the square of the paths.
  EngineCollector collector;
  std::unordered_set<const SoNode*> seen;
  for (std::vector<SoNode*> next{root}; !next.empty();) {
    SoNode* node = next.back();
    next.pop_back();
    if (!node || !seen.insert(node).second) continue;
    collector.visit(node);
    if (const SoChildList* children = node->getChildren())
      for (int i = children->getLength() - 1; i >= 0; --i) next.push_back((*children)[i]);
  }
  return collector.engines;
}

}  // namespace figment
