#pragma once
// A horizontal square of cloth, 1 m^2, falling from y = 1 m at steps of 1 ms: the smallest
// drape that runs, read from text with fields added to its engine, draping with a drape
// context of the test's own (as a session hands one to each engine).

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoSeparator.h>

#include <memory>
#include <string>

#include "nodes/Init.h"
#include "nodes/cloth/ClothEngine.h"
#include "nodes/cloth/DrapeContext.h"

namespace figment::test {

class FallingSquare {
 public:
  // Falls for `seconds`; `fields` go into the engine's body as written.
  explicit FallingSquare(double seconds, const std::string& fields = "",
                         std::shared_ptr<DrapeContext> context = std::make_shared<DrapeContext>())
      : context_(std::move(context)) {
    figment::init();
    const std::string text =
        "#Inventor V2.1 ascii\nSeparator {\n  DEF Points Coordinate3 { point = DEF Drape ClothEngine {\n"
        "    restPoints [ -0.5 1 -0.5, 0.5 1 -0.5, 0.5 1 0.5, -0.5 1 0.5 ]\n"
        "    coordIndex [ 0 3 2 1 -1 ]  timeStep 0.001  maxTime " +
        std::to_string(seconds) + "\n    " + fields +
        "\n  } . positions }\n  IndexedFaceSet { coordIndex [ 0 3 2 1 -1 ] }\n}\n";
    SoInput in;
    in.setBuffer(text.data(), text.size());
    root_ = SoDB::readAll(&in);
    if (!root_) return;
    root_->ref();
    points_ = static_cast<SoCoordinate3*>(root_->getChild(0));
    engine_ = static_cast<ClothEngine*>(SoEngine::getByName("Drape"));
    if (engine_) engine_->setDrapeContext(context_);
  }
  ~FallingSquare() {
    if (root_) root_->unref();
  }
  FallingSquare(const FallingSquare&) = delete;
  FallingSquare& operator=(const FallingSquare&) = delete;

  bool read() const { return root_ && engine_; }
  ClothEngine& engine() const { return *engine_; }
  SoCoordinate3& points() const { return *points_; }
  const std::shared_ptr<DrapeContext>& context() const { return context_; }
  // Drapes, if it has not: the drawn points ask the engine for its output.
  void drape() const { (void)points_->point.getNum(); }

 private:
  std::shared_ptr<DrapeContext> context_;
  SoSeparator* root_ = nullptr;
  SoCoordinate3* points_ = nullptr;
  ClothEngine* engine_ = nullptr;
};

}  // namespace figment::test
