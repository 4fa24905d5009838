#include "session/SceneSession.h"

#include <Inventor/SoPath.h>
#include <Inventor/nodes/SoSeparator.h>

#include "guard/Guard.h"
#include "nodes/SceneSearch.h"
#include "nodes/render/ClothingLayer.h"
#include "session/SceneStaging.h"
#include "sim/drape/DrapeReport.h"

namespace figment::session {

SceneSession::SceneSession() : SceneSession(std::make_shared<DrapeContext>()) {}

SceneSession::SceneSession(std::shared_ptr<DrapeContext> context)
    : context_(context ? std::move(context) : std::make_shared<DrapeContext>()) {}

SceneSession::~SceneSession() {
  clear();
}

void SceneSession::clear() {
  for (ClothEngine* engine : engines_) engine->setDrapeContext(nullptr);  // one held elsewhere drapes alone
  if (staged_) staged_->unref();
  if (scene_) scene_->unref();
  staged_ = scene_ = nullptr;
  engines_.clear();
  shapeError_.clear();
  shapesChecked_ = false;
}

bool SceneSession::load(const std::string& path) {
  clear();
  scene_ = guard::readScene(path, loadError_);
  if (!scene_) return false;
  engines_ = findClothEngines(scene_);
  for (ClothEngine* engine : engines_) engine->setDrapeContext(context_);
  return true;
}

void SceneSession::adopt(SoSeparator* scene) {
  clear();
  scene_ = scene;
  if (!scene_) return;
  scene_->ref();
  engines_ = findClothEngines(scene_);
  for (ClothEngine* engine : engines_) engine->setDrapeContext(context_);
}

const std::vector<ClothEngine*>& SceneSession::drape() {
  std::vector<int> before;
  for (const ClothEngine* engine : engines_) before.push_back(engine->evaluationCount());
  for (size_t i = 0; i < engines_.size(); ++i) {
    ClothEngine* engine = engines_[i];
    // Reading the output simulates when an input changed; skipped when reading an
    // engine before it (one it feeds) has simulated it already. An engine whose output
    // nothing reads does not simulate (its run stays zeros).
    if (engine->evaluationCount() == before[i] && engine->positions.getNumConnections() > 0)
      engine->positions[0]->evaluate();
  }
  shapeError_.clear();
  shapesChecked_ = false;
  if (firstError().empty()) checkShapes();  // a failed drape is its own error, and stages nothing
  return engines_;
}

void SceneSession::checkShapes() {
  // Draped, the coordinates are known: every shape's indices and counts must lie within its
  // data before anything is drawn or bounded (Coin allocates by the largest index).
  shapeError_ = guard::checkShapes(scene_);
  // And the fields that say how a layer is drawn (its display mesh's levels).
  const SoPathList layers = findAll(scene_, ClothingLayer::getClassTypeId());
  for (int i = 0; i < layers.getLength() && shapeError_.empty(); ++i)
    shapeError_ = static_cast<ClothingLayer*>(layers[i]->getTail())->fieldProblem();
  shapesChecked_ = true;
}

std::vector<std::string> SceneSession::verdicts() const {
  std::vector<std::string> lines;
  for (const ClothEngine* engine : engines_)
    if (engine->lastError().empty() && !engine->lastRun().verdict.empty())
      lines.push_back(engine->label() + ": " + engine->lastRun().verdict);
  return lines;
}

std::string SceneSession::firstError() const {
  for (const ClothEngine* engine : engines_)
    if (!engine->lastError().empty()) return engine->lastError();
  return shapeError_;
}

SoSeparator* SceneSession::stage(const ImageSize& size, const std::optional<ViewDirection>& view) {
  if (!shapesChecked_) checkShapes();
  if (!shapeError_.empty()) return nullptr;  // the box would be read past the shapes' data
  return stage(size, view, sceneBox(scene_, size));
}

SoSeparator* SceneSession::stage(const ImageSize& size, const std::optional<ViewDirection>& view, const SbBox3f& box,
                                 float distance) {
  if (!shapesChecked_) checkShapes();
  if (!shapeError_.empty()) return nullptr;
  if (staged_) staged_->unref();
  stagedBox_ = box;
  staged_ = stageScene(scene_, size, view, stagedBox_, distance);
  staged_->ref();
  return staged_;
}

}  // namespace figment::session
