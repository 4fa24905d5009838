#include "nodes/SceneSearch.h"

#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>

namespace figment {

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

}  // namespace figment
