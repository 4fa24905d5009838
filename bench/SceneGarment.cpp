#include "SceneGarment.h"

#include "nodes/Init.h"

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/engines/SoEngineOutput.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace figment::bench {

bool SceneGarment::load(const std::string& scene, std::string& error) {
  figment::init();
  SoInput input;
  if (!input.openFile(scene.c_str())) {
    error = scene + ": cannot open the scene";
    return false;
  }
  root = SoDB::readAll(&input);
  if (!root) {
    error = scene + ": cannot read the scene";
    return false;
  }
  root->ref();
  const std::vector<ClothEngine*> engines = findClothEngines(root);
  if (engines.empty()) {
    error = scene + ": no ClothEngine";
    return false;
  }
  engine = engines.front();
  SoSearchAction search;
  search.setType(SoCoordinate3::getClassTypeId());
  search.setInterest(SoSearchAction::ALL);
  search.apply(root);
  for (int i = 0; i < search.getPaths().getLength() && !coordinates; ++i) {
    auto* candidate = static_cast<SoCoordinate3*>(search.getPaths()[i]->getTail());
    SoEngineOutput* output = nullptr;
    if (candidate->point.getConnectedEngine(output) && output == &engine->positions) coordinates = candidate;
  }
  if (!coordinates) {
    error = scene + ": no Coordinate3 fed by " + engine->label();
    return false;
  }
  rest.assign(engine->restPoints.getValues(0), engine->restPoints.getValues(0) + engine->restPoints.getNum());
  std::set<std::array<int, 2>> unique;
  std::vector<int> face;
  for (int i = 0; i < engine->coordIndex.getNum(); ++i) {
    const int index = engine->coordIndex[i];
    if (index >= 0) face.push_back(index);
    if (index < 0 || i + 1 == engine->coordIndex.getNum()) {
      for (size_t k = 0; k < face.size(); ++k) {
        const int a = face[k], b = face[(k + 1) % face.size()];
        unique.insert({std::min(a, b), std::max(a, b)});
      }
      face.clear();
    }
  }
  edges.assign(unique.begin(), unique.end());
  return true;
}

void SceneGarment::release() {
  if (root) root->unref();
  root = nullptr;
}

std::vector<SbVec3f> SceneGarment::drape() {
  const SbVec3f* draped = coordinates->point.getValues(0);  // evaluates the engine when an input changed
  return {draped, draped + coordinates->point.getNum()};
}

double SceneGarment::maxEdgeStrain(const std::vector<SbVec3f>& positions) const {
  double worst = 0.0;
  for (const auto& [a, b] : edges) {
    const double restLength = (rest[a] - rest[b]).length();
    const double length = (positions[a] - positions[b]).length();
    if (restLength > 0.0) worst = std::max(worst, std::abs(length / restLength - 1.0));
  }
  return worst;
}

}  // namespace figment::bench
