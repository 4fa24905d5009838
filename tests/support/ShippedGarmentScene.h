#pragma once
// A shipped scene (scenes/<name>) with one garment: read with scenes/ on the model path
// (kept for the object's life, so the body loads when the engine drapes), and its
// ClothEngine.

#include <string>
#include <vector>

#include "nodes/SceneSearch.h"
#include "nodes/cloth/ClothEngine.h"
#include "support/SceneTestSupport.h"

namespace figment::test {

class ShippedGarmentScene {
 public:
  explicit ShippedGarmentScene(const std::string& name) : modelPath_(FIGMENT_SOURCE_DIR "/scenes") {
    initCoin();
    root_ = readFile(FIGMENT_SOURCE_DIR "/scenes/" + name);
    if (root_) engines_ = figment::findClothEngines(root_.get());
  }

  // Null unless the scene read and holds exactly one engine.
  ClothEngine* engine() const { return engines_.size() == 1 ? engines_.front() : nullptr; }
  SoSeparator* root() const { return root_.get(); }

 private:
  ScopedModelPath modelPath_;
  SceneRoot root_;
  std::vector<ClothEngine*> engines_;
};

}  // namespace figment::test
