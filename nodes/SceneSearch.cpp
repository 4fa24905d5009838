#include "nodes/SceneSearch.h"

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

}  // namespace figment
