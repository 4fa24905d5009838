// figment-view: renders a FIGMENT scene (.iv) to a PNG image, headless.
//
//   figment-view SCENE.iv -o OUT.png [--size WxH] [--view front|back|left|right|AZ,EL]
//                [--stats OUT.json] [--depth-buffer-only] [--keep-stencil-fields]
//                [--show-volumes] [--stop-at N] [--no-cache]
//
// Every error is one line on stderr, "figment-view: <file>: <what>", and a non-zero
// exit status (2: bad command line, 1: anything else, an exception included); no image
// is written then.

#include "io/DrapeCache.h"
#include "nodes/FaceIndexCheck.h"
#include "nodes/body/Mannequin.h"
#include "nodes/cloth/ClothEngine.h"
#include "nodes/SceneSearch.h"
#include "viewer/DepthBufferOnly.h"
#include "viewer/OffscreenContext.h"
#include "viewer/SceneRenderer.h"
#include "viewer/SceneSession.h"
#include "viewer/StatsJson.h"
#include "viewer/ViewOptions.h"

#include <CLI/CLI.hpp>
#include <Inventor/SoPath.h>
#include <Inventor/nodes/SoSeparator.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <utility>

namespace {

struct Options {
  std::string scene;
  std::string output;
  std::string size = "800x600";
  std::string view;
  std::string stats;
  bool keepStencilFields = false;
  bool depthBufferOnly = false;
  bool showVolumes = false;
  bool noCache = false;
  int stopAt = 0;  // steps; 0: no bound
};

constexpr std::uintmax_t kCacheBytes = 512u << 20;  // the drape cache's bound

int fail(const std::string& where, const std::string& message, int status = 1) {
  std::cerr << "figment-view: " << where << ": " << message << "\n";
  return status;
}

// The image just written, removed again unless the run succeeds: an error after it (the
// statistics, an exception) leaves no image behind.
class WrittenImage {
 public:
  explicit WrittenImage(std::string path) : path_(std::move(path)) {}
  ~WrittenImage() {
    std::error_code ignored;
    if (!kept_) std::filesystem::remove(path_, ignored);
  }
  WrittenImage(const WrittenImage&) = delete;
  WrittenImage& operator=(const WrittenImage&) = delete;
  void keep() { kept_ = true; }

 private:
  std::string path_;
  bool kept_ = false;
};

// Long simulations say how far they are, about once a second.
void reportProgress(const ClothEngine& engine, const ClothEngine::Progress& p) {
  std::fprintf(stderr, "figment-view: %s: simulated %.3g of %.3g s (%d steps, %.1f s, fastest node %.3g m/s)\n",
               engine.label().c_str(), p.simulatedSeconds, p.maxTime, p.iterations, p.wallSeconds, p.maxSpeed);
}

void reportFinished(const figment::viewer::EngineDrape& drape) {
  const ClothEngine::RunStats& run = drape.run;
  if (run.wallSeconds < 1.0) return;  // short runs stay quiet
  std::fprintf(stderr, "figment-view: %s: %s after %.3g s simulated (%d steps, %.1f s)\n", drape.label.c_str(),
               run.atRest ? "at rest" : "stopped at maxTime", run.simulatedSeconds, run.iterations,
               run.wallSeconds);
}

// Before anything simulates: a Mannequin's fields feed the engines that use it.
void showVolumes(SoNode* scene) {
  const SoPathList mannequins = figment::findAll(scene, Mannequin::getClassTypeId());
  for (int i = 0; i < mannequins.getLength(); ++i)
    static_cast<Mannequin*>(mannequins[i]->getTail())->showVolumes = TRUE;
}

// --stop-at: every drape stops after `steps` steps, if not at rest before (to show a
// progressive drape's growth, say).
void stopAt(SoNode* scene, int steps) {
  for (ClothEngine* engine : figment::findClothEngines(scene))
    engine->maxTime = std::min(engine->maxTime.getValue(), steps * engine->timeStep.getValue());
}

// Finished drapes are kept in the user's cache folder (none without one).
void useDrapeCache(bool use) {
  const std::filesystem::path folder = figment::DrapeCache::userFolder();
  if (use && !folder.empty()) ClothEngine::setDrapeCache(std::make_shared<figment::DrapeCache>(folder, kCacheBytes));
}

// Drapes every engine; its errors come before any image. "" or the first error.
std::string drapeAll(figment::viewer::SceneSession& session) {
  ClothEngine::setProgressCallback(reportProgress);
  for (const figment::viewer::EngineDrape& drape : session.drape()) {
    if (!drape.error.empty()) return drape.error;
    reportFinished(drape);
  }
  for (ClothEngine* engine : session.engines())  // the cache's trouble is said, not fatal
    if (!engine->lastCacheMessage().empty())
      std::fprintf(stderr, "figment-view: %s: %s\n", engine->label().c_str(), engine->lastCacheMessage().c_str());
  return "";
}

int render(const Options& options, const figment::viewer::ImageSize& size,
           const std::optional<figment::viewer::ViewDirection>& view) {
  using namespace figment::viewer;
  initHeadless();
  SceneSession session;
  if (!session.load(options.scene)) return fail(options.scene, session.loadError());
  if (options.showVolumes) showVolumes(session.scene());
  if (options.stopAt > 0) stopAt(session.scene(), options.stopAt);
  useDrapeCache(!options.noCache);
  std::string error = drapeAll(session);
  if (!error.empty()) return fail(options.scene, error);
  // Draped, the coordinates are known: every face set's indices must lie among them
  // before anything is drawn or bounded (Coin allocates by the largest index).
  error = figment::firstFaceIndexError(session.scene());
  if (!error.empty()) return fail(options.scene, error);
  SoSeparator* root = session.stage(size, view);

  DepthBufferOnly plain(root);
  plain.use(options.depthBufferOnly);
  SceneRenderer renderer(size);
  const auto start = std::chrono::steady_clock::now();
  error = renderer.render(root, options.keepStencilFields);
  const std::chrono::duration<double> renderWall = std::chrono::steady_clock::now() - start;
  if (!error.empty()) return fail(options.scene, error);
  error = renderer.writePng(options.output);
  if (!error.empty()) return fail(options.output, error);
  WrittenImage image(options.output);
  if (!options.stats.empty()) {
    error = writeStatsJson(options.stats, options.scene, session.drapes(), renderWall.count(), size);
    if (!error.empty()) return fail(options.stats, error);
  }
  image.keep();
  return 0;
}

// An exception's message as one line.
std::string oneLine(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

int run(int argc, char** argv, Options& options) {
  CLI::App app{"figment-view: renders a FIGMENT scene (.iv) to a PNG image, headless."};
  app.add_option("scene", options.scene, "Scene file (.iv)")->required();
  app.add_option("-o,--output", options.output, "PNG image to write")->required();
  app.add_option("--size", options.size, "Image size in pixels, WxH")->capture_default_str();
  app.add_option("--view", options.view,
                 "Camera direction: front, back, left, right or AZ,EL in degrees "
                 "(default: the scene's camera, else front)");
  app.add_option("--stats", options.stats, "Write simulation and render statistics (JSON) here");
  app.add_flag("--depth-buffer-only", options.depthBufferOnly,
               "Draw ClothingLayer, DepthSortedGroup and StencilSeparator as IndexedFaceSet, Group and "
               "Separator: the depth buffer alone, to compare with the hybrid rendering");
  app.add_flag("--keep-stencil-fields", options.keepStencilFields,
               "Render with the scene's StencilSeparator.writeStencil and ClothingLayer.masked values, "
               "not those the stencil rule sets for the camera");
  app.add_option("--stop-at", options.stopAt, "Stop every drape after this many steps (if not at rest before)")
      ->check(CLI::PositiveNumber);
  app.add_flag("--show-volumes", options.showVolumes,
               "Draw every Mannequin's collision volumes as wireframes over the body");
  app.add_flag("--no-cache", options.noCache,
               "Drape even where the drape cache ($XDG_CACHE_HOME/figment, else ~/.cache/figment) holds this "
               "drape, and keep nothing there");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return fail("usage", std::string(e.what()) + " (see --help)", 2);
  }

  const auto size = figment::viewer::parseImageSize(options.size);
  if (!size) return fail("--size", "'" + options.size + "' is not WxH with 1 to 16384 pixels each (e.g. 800x600)", 2);
  std::optional<figment::viewer::ViewDirection> view;
  if (!options.view.empty()) {
    view = figment::viewer::parseViewDirection(options.view);
    if (!view)
      return fail("--view",
                  "'" + options.view + "' is not front, back, left, right or AZ,EL in degrees with -90 < EL < 90",
                  2);
  }
  return render(options, *size, view);
}

}  // namespace

// Nothing escapes the program: an exception from anywhere (a library's, std::bad_alloc)
// is one line and exit status 1, as every other error.
int main(int argc, char** argv) {
  Options options;
  const auto where = [&] { return options.scene.empty() ? std::string("error") : options.scene; };
  try {
    return run(argc, argv, options);
  } catch (const std::exception& e) {
    return fail(where(), std::string("unexpected error: ") + oneLine(e.what()));
  } catch (...) {
    return fail(where(), "unexpected error of an unknown type");
  }
}
