#pragma once
// The guard's shape data checks as the guard runs them: on each shape of a scene read from
// text, with the state a callback traversal has there (coordinates, bindings).

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoShape.h>

#include <functional>
#include <string>
#include <vector>

namespace figment::guard::shapes::test {

// `check`'s answer for every shape of `scene` (an .iv text), in scene order.
inline std::vector<std::string> problemsOfShapes(const std::string& scene,
                                                 const std::function<std::string(const SoShape&, SoState*)>& check) {
  SoDB::init();
  SoInput in;
  in.setBuffer(scene.data(), scene.size());
  SoSeparator* root = SoDB::readAll(&in);
  std::vector<std::string> problems;
  if (!root) return {"the scene did not read"};
  root->ref();
  struct Visit {
    const std::function<std::string(const SoShape&, SoState*)>* check;
    std::vector<std::string>* problems;
  } visit{&check, &problems};
  SoCallbackAction action;
  action.addPreCallback(
      SoShape::getClassTypeId(),
      [](void* data, SoCallbackAction* a, const SoNode* node) {
        auto* v = static_cast<Visit*>(data);
        v->problems->push_back((*v->check)(*static_cast<const SoShape*>(node), a->getState()));
        return SoCallbackAction::PRUNE;
      },
      &visit);
  action.apply(root);
  root->unref();
  return problems;
}

}  // namespace figment::guard::shapes::test
