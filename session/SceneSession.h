#pragma once
// One scene, from file to staged root: load -> drape every engine -> stage, written once
// for every front end (figment-view, figment-bench, a service). Rendering the staged root
// is SceneRenderer's.

#include <Inventor/SbBox3f.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "nodes/body/CollisionBody.h"
#include "nodes/cloth/ClothEngine.h"
#include "nodes/cloth/DrapeContext.h"
#include "session/SessionOptions.h"

class SoSeparator;

namespace figment::session {

// The session holds the scene (and, once staged, the staged root) until it is cleared or
// destroyed, and the drape context its engines drape with: its own drape cache (none
// unless the front end sets one), observers and broad phase, shared with no other
// session. Coin must be initialised first (figment::initHeadless(), headless/InitHeadless.h, to render;
// figment::init() is enough to drape); read errors come as one line only after
// initHeadless().
class SceneSession {
 public:
  // A session with a context of its own (no cache, no observers), or the one given.
  SceneSession();
  explicit SceneSession(std::shared_ptr<DrapeContext> context);
  ~SceneSession();
  SceneSession(const SceneSession&) = delete;
  SceneSession& operator=(const SceneSession&) = delete;

  // What this session's engines drape with. Set it between drapes, never during one.
  DrapeContext& context() { return *context_; }
  const DrapeContext& context() const { return *context_; }
  const std::shared_ptr<DrapeContext>& sharedContext() const { return context_; }

  // Reads the scene in `path` through the guard (guard::readScene), finds its ClothEngines
  // (in scene order, figment::findClothEngines) and hands each the session's context;
  // nothing simulates yet. Returns false, with loadError() one line ("no such file",
  // "line 12: Unknown class \"Foo\""), on failure.
  bool load(const std::string& path);
  // Takes `scene`, a graph a front end built in code from its own nodes (a service's, from
  // a request's parameters: no scene text is read), as load() takes a file's: finds its
  // ClothEngines and hands each the session's context. The session references it.
  void adopt(SoSeparator* scene);
  const std::string& loadError() const { return loadError_; }

  // Simulates every engine whose output something reads, one after another in scene
  // order (an engine another one feeds from simulates when that one does), and keeps
  // each one's result. Again after an engine's input changed: simulates those again.
  // Then, when every drape succeeded, checks the shapes against the data they now draw
  // (guard::checkShapes): shapeError().
  // Returns the engines, in scene order: each one's lastRun() says what it draped and how
  // (sim/drape/DrapeReport.h: the method that ran, what it collided with, the run, the
  // verdict), its lastError() why it failed ("" when it succeeded).
  const std::vector<ClothEngine*>& drape();
  // The guard's check of the shapes after the last drape: "" when every shape indexes and
  // counts only the data it has, and every ClothingLayer's drawing fields are in range
  // (ClothingLayer::fieldProblem), else one line ("ClothingLayer 'Layer': coordIndex[3] = ...").
  const std::string& shapeError() const { return shapeError_; }
  // The drapes of the last drape() that succeeded but are not clean (not at rest, torn,
  // limited at the end, failed implicit steps: DrapeReport::verdict), one line
  // each naming the engine, in scene order: "ClothEngine 'Dress': not at rest after
  // maxTime 10 s (max speed 0.31 m/s)". A front end says them (figment-view on stderr)
  // or, strict, refuses the drape.
  std::vector<std::string> verdicts() const;
  // The first engine's error, in scene order, else the shapes' (shapeError()); "" when every
  // drape succeeded and every shape may be drawn.
  std::string firstError() const;

  // Puts the scene under a root with the camera and light it lacks (see stageScene),
  // looking from `view` (the scene's own camera when none is given). Drape first: the
  // bounding box read here then shows the draped garments. Null, with nothing staged, when
  // the shapes failed their check (shapeError(); checked here when the scene was not draped):
  // Coin would bound and draw past their data.
  SoSeparator* stage(const ImageSize& size, const std::optional<ViewDirection>& view);
  // The same, framing `box` (frames of a time span share one camera: the box of them all),
  // from `distance` when it is positive (the views of a turntable share one: see
  // framingDistance).
  SoSeparator* stage(const ImageSize& size, const std::optional<ViewDirection>& view, const SbBox3f& box,
                     float distance = 0.0f);

  // Takes the context back from the engines and unreferences the scene and the staged
  // root; the session is empty again (its context stays).
  void clear();

  SoSeparator* scene() const { return scene_; }
  SoSeparator* stagedRoot() const { return staged_; }
  // The scene's bounding box when it was staged (what the framing camera frames).
  const SbBox3f& stagedBox() const { return stagedBox_; }
  const std::vector<ClothEngine*>& engines() const { return engines_; }

 private:
  void checkShapes();

  SoSeparator* scene_ = nullptr;   // referenced
  SoSeparator* staged_ = nullptr;  // referenced
  SbBox3f stagedBox_;
  std::string loadError_;
  std::string shapeError_;
  bool shapesChecked_ = false;             // since the scene was loaded or last draped
  std::shared_ptr<DrapeContext> context_;  // never null
  std::vector<ClothEngine*> engines_;
};

}  // namespace figment::session
