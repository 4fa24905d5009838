#include "serve/workers/RenderWorker.h"

#include <Inventor/nodes/SoSeparator.h>

#include <cstdio>
#include <nlohmann/json.hpp>

#include "io/DrapeCache.h"
#include "io/GarmentCatalogue.h"
#include "io/PngFile.h"
#include "nodes/body/HumanBody.h"
#include "serve/request/FitRequest.h"
#include "serve/request/RenderRequest.h"
#include "serve/scene/DrapeState.h"
#include "serve/scene/OutfitScene.h"
#include "serve/workers/FrameChannel.h"
#include "serve/workers/RedisStore.h"
#include "session/SceneExport.h"

namespace figment::serve {

namespace {

constexpr std::uintmax_t kCacheBytes = 1024u << 20;  // the drape cache's bound on disk

RenderWorker::Answer failure(int status, const std::string& error) {
  return {status, nlohmann::json{{"error", error}}.dump(), false, ""};
}

// The request parameter of a fit goal's key (sim/body/BodyMeasurements.h), or "".
std::string parameterOf(const std::string& key) {
  if (key == "stature") return key;
  if (key == "bust_girth") return "bust";
  if (key == "waist_girth") return "waist";
  if (key == "hip_girth") return "hips";
  return "";
}

// 422 for a measured body out of MakeHuman's reach, naming the measurement the fit gave up
// on, what was asked and the nearest it reaches with the others ("waist_girth 0.880 m is out
// of reach with the other measurements: the nearest is 0.790 m").
RenderWorker::Answer unreachableBody(const RenderRequest& request, const std::string& why) {
  const std::string parameter = parameterOf(why.substr(0, why.find(' ')));
  const double values[] = {request.body.stature, request.body.bust, request.body.waist, request.body.hips};
  const char* const names[] = {"stature", "bust", "waist", "hips"};
  std::string value;
  for (size_t i = 0; i < 4; ++i)
    if (parameter == names[i]) {
      char text[32];
      std::snprintf(text, sizeof text, "%.3f", values[i]);
      value = text;
    }
  const size_t nearest = why.find("the nearest is ");
  const std::string accepted = nearest == std::string::npos
                                   ? "a body MakeHuman can make"
                                   : why.substr(nearest + 15) + " (the nearest with the other measurements as given)";
  const nlohmann::json body = {{"error", "no body of these measurements can be made: " + why},
                               {"parameter", parameter},
                               {"value", value},
                               {"accepted", accepted}};
  return {422, body.dump(), false, ""};
}

}  // namespace

RenderWorker::RenderWorker(const std::string& scenesFolder, const std::string& cacheFolder, const std::string& redisUrl,
                           long redisTtl) {
  startError_ = wardrobe_.read(scenesFolder);
  // The server read the same catalogue and, when it could not, draws the Mannequin alone
  // and refuses fits: no made body comes.
  if (wardrobe_.catalogue()) fit_ = std::make_unique<FitWorker>(wardrobe_.catalogue()->chart(), wardrobe_.catalogue());
  if (cacheFolder.empty()) return;
  std::shared_ptr<RedisStore> shared;
  if (!redisUrl.empty()) {
    // Quiet: the server says once whether Redis is there; its workers would say it N times.
    RedisConnection::Options quiet;
    quiet.commandTimeout = 1.0;  // s
    shared = std::make_shared<RedisStore>(std::make_shared<RedisConnection>(redisUrl, quiet), redisTtl);
  }
  session_.context().cache = std::make_shared<DrapeCache>(cacheFolder, kCacheBytes, shared);
  if (fit_) fit_->useCache(session_.context().cache);  // the size drapes beside the engines' drapes
}

void RenderWorker::adviceThreads(unsigned threads) {
  if (fit_) fit_->drapeSizesOn(threads);
}

RenderWorker::~RenderWorker() {
  session_.clear();
  for (const auto& [key, body] : restBodies_) body->unref();
}

HumanBody* RenderWorker::restBody(const RenderRequest& request) {
  const Sex sex = request.sex == "male" ? Sex::Male : Sex::Female;
  const std::string key = FitWorker::bodyKey(request.body, sex);
  if (auto kept = restBodies_.find(key); kept != restBodies_.end()) return kept->second;
  constexpr size_t kKept = 4;  // a worker serves a few shoppers at a time
  if (restBodies_.size() >= kKept) {
    for (const auto& [old, body] : restBodies_) body->unref();  // the held scene keeps its own
    restBodies_.clear();
  }
  HumanBody* body = OutfitScene::makeBody(request);  // throws BodyNotMade
  restBodies_.emplace(key, body);
  // The same mesh the advice drapes on: given to the fit, so it is not made twice.
  if (fit_) fit_->keepBody(request.body, sex, body->collisionSurface());
  return body;
}

void RenderWorker::serve(const FrameChannel& channel) {
  constexpr auto kNever = FrameChannel::Clock::time_point::max();
  std::string kindName, canonical;
  // Two frames a request: its kind, then its canonical text (WorkerPool::makeOn sends them so).
  while (channel.receive(kindName, kNever) == FrameChannel::Result::kOk &&
         channel.receive(canonical, kNever) == FrameChannel::Result::kOk) {
    Answer made;
    try {
      const std::optional<JobKind> kind = jobKindNamed(kindName);
      made = kind ? answer({*kind, canonical}) : failure(400, "no such job kind: " + kindName);
    } catch (const std::exception& e) {
      made = failure(500, e.what());
      sceneKey_.clear();  // the scene may be half made: build it again next time
    }
    const nlohmann::json header = {
        {"status", made.status}, {"drapeCache", made.drapeFromCache ? "hit" : "miss"}, {"drape", made.drape}};
    if (!channel.send(header.dump()) || !channel.send(made.body)) return;
  }
}

RenderWorker::Answer RenderWorker::answer(const WorkRequest& request) {
  return request.kind == JobKind::kFit ? advise(request.canonical) : render(request.canonical);
}

RenderWorker::Answer RenderWorker::advise(const std::string& canonical) {
  if (!fit_) return failure(503, "no size chart: size advice is off");
  auto parsed = FitRequest::parseCanonical(canonical, *wardrobe_.catalogue());
  if (auto* error = std::get_if<ParameterError>(&parsed)) return failure(400, error->error);
  FitWorker::Answer answer = fit_->advise(std::get<FitRequest>(parsed));
  return {answer.status, std::move(answer.body), false, ""};
}

RenderWorker::Answer RenderWorker::render(const std::string& canonical) {
  auto parsed = RenderRequest::parseCanonical(canonical, wardrobe_.catalogue());
  if (auto* error = std::get_if<ParameterError>(&parsed)) return failure(400, error->error);
  const RenderRequest& request = std::get<RenderRequest>(parsed);
  if (request.sceneKey() != sceneKey_) {
    sceneKey_.clear();
    fitMaps_.clear();
    std::vector<DrapeReport> drawn;  // the size drapes the scene draws: the advice's
    try {
      OutfitScene::Made made;
      if (fit_) {
        made.graded = [this](const OutfitItem& item, Sex sex) -> const SizeFitter::Graded& {
          return fit_->graded(item.style, sex, item.size);
        };
        made.sewnCut = [this](const RenderRequest& shopper, const OutfitItem& item) {
          return fit_->cutOn(shopper.body, shopper.sex == "male" ? Sex::Male : Sex::Female, item.style, item.size);
        };
        made.sizeDrape = [this](const RenderRequest& shopper, const OutfitItem& item) {
          return fit_->sizeDrape(shopper.body, shopper.sex == "male" ? Sex::Male : Sex::Female, item.style, item.size);
        };
        made.restBody = [this](const RenderRequest& shopper) { return restBody(shopper); };
      }
      session_.adopt(OutfitScene::build(request, wardrobe_, made, &fitMaps_, &drawn));
    } catch (const OutfitScene::BodyNotMade& error) {
      session_.clear();
      if (!fit_) return failure(500, error.what());
      const std::string why = fit_->unreachable(request.body, request.sex == "male" ? Sex::Male : Sex::Female);
      return why.empty() ? failure(500, error.what()) : unreachableBody(request, why);
    }
    std::vector<DrapeReport> drapes = drapeReports(session_.drape());
    drapes.insert(drapes.begin(), drawn.begin(), drawn.end());  // the innermost garment's first
    const std::string error = session_.firstError();
    if (!error.empty()) {
      session_.clear();
      return failure(500, "the outfit did not drape: " + error);
    }
    OutfitScene::paintFitMaps(fitMaps_);
    sceneFromCache_ = true;
    for (const DrapeReport& drape : drapes) sceneFromCache_ = sceneFromCache_ && drape.fromCache;
    sceneKey_ = request.sceneKey();
    sceneDrape_ = drapeState(drapes);
    Answer answer = drawView(request);
    if (answer.status == 200) answer.drape = sceneDrape_;
    return answer;
  }
  Answer answer = drawView(request);
  answer.drapeFromCache = true;  // the scene was kept from the last request: no drape
  if (answer.status == 200) answer.drape = sceneDrape_;
  return answer;
}

RenderWorker::Answer RenderWorker::drawView(const RenderRequest& request) {
  if (request.format == "glb") {
    // The dressed body as meshes (session/SceneExport.h), for a 3D viewer on the page.
    std::string error;
    const std::vector<unsigned char> glb = session::exportGlb(session_.scene(), {true}, error);
    if (!error.empty()) return failure(500, error);
    return {200, std::string(glb.begin(), glb.end()), sceneFromCache_, ""};
  }
  const session::ImageSize size{request.width, request.height};
  if (!session_.stage(size, session::ViewDirection{request.azimuth, request.elevation}))
    return failure(500, "the outfit cannot be drawn: " + session_.shapeError());
  if (!renderer_ || renderer_->size().width != size.width || renderer_->size().height != size.height)
    renderer_ = std::make_unique<session::SceneRenderer>(size, request.supersample());
  if (std::string error = renderer_->render(session_.stagedRoot()); !error.empty()) return failure(500, error);
  Answer answer{200, "", sceneFromCache_, ""};
  if (std::string error = encodePng({size.width, size.height, renderer_->pixels()}, answer.body); !error.empty())
    return failure(500, error);
  return answer;
}

}  // namespace figment::serve
