#pragma once
// A worker process's loop: reads a request's kind and canonical text from the server
// (serve/workers/JobKind.h), and for a render builds its
// scene (OutfitScene), drapes it with the worker's own SceneSession and DrapeContext
// (the drape cache on disk, shared with the other workers), renders the view and sends
// back a JSON header and the PNG. The scene of the last request is kept: another view
// or size of it renders without building or draping again. A fit (serve/request/FitRequest.h)
// goes to the worker's FitWorker instead and answers JSON.

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "serve/scene/OutfitScene.h"
#include "serve/scene/Wardrobe.h"
#include "serve/workers/FitWorker.h"
#include "serve/workers/JobKind.h"
#include "session/SceneRenderer.h"
#include "session/SceneSession.h"

namespace figment::serve {

class FrameChannel;
class RenderRequest;

class RenderWorker {
 public:
  // Drapes kept in `cacheFolder` (none when empty), over Redis at `redisUrl` when one is
  // given (entries kept `redisTtl` s unread); body and patterns from `scenesFolder`.
  RenderWorker(const std::string& scenesFolder, const std::string& cacheFolder, const std::string& redisUrl = "",
               long redisTtl = 0);
  ~RenderWorker();
  RenderWorker(const RenderWorker&) = delete;
  RenderWorker& operator=(const RenderWorker&) = delete;

  // "" when the wardrobe read, else why not (the worker then exits).
  const std::string& startError() const { return startError_; }
  // How many of an advice's sizes drape at once (FitWorker::drapeSizesOn); no effect without a
  // size chart.
  void adviceThreads(unsigned threads);

  // Answers requests until the server closes the channel.
  void serve(const FrameChannel& channel);

  struct Answer {
    int status = 500;
    std::string body;  // PNG, or JSON {"error": ...}
    bool drapeFromCache = false;
    std::string drape;  // a render's: drapeState() of its scene (serve/scene/DrapeState.h); "" else
  };
  // The answer to `request`: a render's picture or a fit's advice.
  Answer answer(const WorkRequest& request);

 private:
  Answer render(const std::string& canonical);
  Answer advise(const std::string& canonical);
  // The request's image (or GLB) of the scene the session holds, draped.
  Answer drawView(const RenderRequest& request);

  Wardrobe wardrobe_;
  std::string startError_;
  session::SceneSession session_;
  std::string sceneKey_;  // the request whose scene the session holds; "" for none
  bool sceneFromCache_ = false;
  std::string sceneDrape_;  // drapeState() of the held scene
  std::unique_ptr<session::SceneRenderer> renderer_;
  std::unique_ptr<FitWorker> fit_;                   // null when the size chart did not read
  std::vector<OutfitScene::FitMapGarment> fitMaps_;  // the held scene's garments drawn as fit maps
  // Made bodies at rest, by sex and measurements, referenced: the last few, so another
  // size, style or view of a shopper's body does not make the body again (0.4 s).
  std::map<std::string, HumanBody*> restBodies_;
  HumanBody* restBody(const RenderRequest& request);
};

}  // namespace figment::serve
