// figment-view: renders a FIGMENT scene (.iv) to PNG images, headless.
//
//   figment-view SCENE.iv -o OUT.png [--size WxH] [--view front|back|left|right|AZ,EL]...
//                [--turntable N] [--frames T0:T1:N] [--wind-force OUT.csv]
//                [--stats OUT.json] [--fit-map stretch|ease|pressure]
//                [--depth-buffer-only] [--keep-stencil-fields]
//                [--show-volumes] [--display-subdivision N] [--stop-at N] [--no-cache] [--strict]
//                [--export OUT.glb|.gltf|.obj [--export-body]]
//   figment-view --list-nodes
//
// The scene drapes once, however many images it gives (views, a turntable, or the
// frames of a time span); every image is written atomically. Every error is one line on
// stderr, "figment-view: <file or option>: <what>", and a non-zero exit status (2: bad
// command line, 1: anything else, an exception included); no image or export is left then.
// A drape that is not clean (its verdict: not at rest, torn, limited, failed steps) is one
// line too, and with --strict an error.

#include <Inventor/SoDB.h>
#include <Inventor/SoPath.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoSeparator.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "headless/InitHeadless.h"
#include "io/DrapeCache.h"
#include "io/MakeHumanLibrary.h"
#include "nodes/Init.h"
#include "nodes/SceneSearch.h"
#include "nodes/body/Mannequin.h"
#include "nodes/cloth/ClothEngine.h"
#include "nodes/render/ClothingLayer.h"
#include "session/DrapeRecorder.h"
#include "session/EngineFit.h"
#include "session/FitMapDrawing.h"
#include "session/FrameDisplay.h"
#include "session/SceneExport.h"
#include "session/SceneRenderer.h"
#include "session/SceneSession.h"
#include "session/SceneStaging.h"
#include "sim/drape/DrapeReport.h"
#include "viewer/DepthBufferOnly.h"
#include "viewer/ImagePlan.h"
#include "viewer/NodeCatalog.h"
#include "viewer/PrintableLine.h"
#include "viewer/ProgressBar.h"
#include "viewer/StatsJson.h"
#include "viewer/ViewOptions.h"
#include "viewer/WindForceCsv.h"

namespace {

using figment::session::DrapeRecorder;
using figment::session::SceneRenderer;
using figment::session::SceneSession;
using figment::viewer::ImagePlan;

// --supersample's default: 3 x 3 samples a pixel smooth the edges (256 grey levels
// would need 16 x 16; 9 levels already hide the stair steps) at about twice the render
// time of one sample.
constexpr int kDefaultSupersample = 3;

struct Options {
  std::string scene;
  std::string output;
  std::string size = "800x600";
  std::vector<std::string> views;
  std::string turntable;
  std::string frames;
  std::string windForce;
  std::string stats;
  std::string fitMap;      // --fit-map: stretch, ease or pressure; "" = the scene's colours
  std::string exportPath;  // --export; "" = none
  bool exportBody = false;
  bool keepStencilFields = false;
  bool depthBufferOnly = false;
  bool showVolumes = false;
  bool noCache = false;
  bool listNodes = false;
  bool strict = false;
  int stopAt = 0;               // steps; 0: no bound
  int displaySubdivision = -1;  // every ClothingLayer's; -1: as the scene says
  int supersample = kDefaultSupersample;
};

constexpr std::uintmax_t kCacheBytes = 512u << 20;  // the drape cache's bound
// --wind-force samples the force about this often (s simulated; at most once a step).
constexpr double kWindSampleSpacing = 1.0 / 200.0;

int fail(const std::string& where, const std::string& message, int status = 1) {
  // One line whatever the input held: names and values come from the command line and
  // the scene, and may hold line breaks or control bytes.
  std::cerr << "figment-view: " << figment::viewer::printableLine(where + ": " + message) << "\n";
  return status;
}

// The images (and export files) written so far, removed again unless the run succeeds:
// an error after them (another image, the statistics, an exception) leaves none behind.
class WrittenImages {
 public:
  WrittenImages() = default;
  ~WrittenImages() {
    std::error_code ignored;
    if (!kept_)
      for (const std::string& path : paths_) std::filesystem::remove(path, ignored);
  }
  WrittenImages(const WrittenImages&) = delete;
  WrittenImages& operator=(const WrittenImages&) = delete;
  void add(std::string path) { paths_.push_back(std::move(path)); }
  void keep() { kept_ = true; }

 private:
  std::vector<std::string> paths_;
  bool kept_ = false;
};

// Long simulations say how far they are: on a terminal a bar redrawn in place, else
// (logs, tests) a line about once a second.
void reportProgress(figment::viewer::ProgressBar& bar, const ClothEngine& engine, const ClothEngine::Progress& p) {
  if (bar.shown()) {
    bar.draw(figment::viewer::progressBarLine(engine.label(), p.simulatedSeconds, p.maxTime, p.wallSeconds));
    return;
  }
  std::fprintf(stderr, "figment-view: %s: simulated %.3g of %.3g s (%d steps, %.1f s, fastest node %.3g m/s)\n",
               engine.label().c_str(), p.simulatedSeconds, p.maxTime, p.iterations, p.wallSeconds, p.maxSpeed);
}

// A drape that is not clean says so in one line, however long it took (its verdict,
// figment::DrapeReport::verdict); a clean one only when it took a second or more.
void reportFinished(const std::string& scene, const ClothEngine& engine) {
  const figment::DrapeReport& report = engine.lastRun();
  if (!report.verdict.empty()) {
    std::cerr << "figment-view: "
              << figment::viewer::printableLine(scene + ": " + engine.label() + ": " + report.verdict) << "\n";
    return;
  }
  if (report.wallSeconds < 1.0) return;  // short clean runs stay quiet
  std::fprintf(stderr, "figment-view: %s: at rest after %.3g s simulated (%d steps, %.1f s)\n", engine.label().c_str(),
               report.run.simulatedTime, report.run.iterations, report.wallSeconds);
}

// Before anything simulates: a Mannequin's fields feed the engines that use it.
void showVolumes(SoNode* scene) {
  const SoPathList mannequins = figment::findAll(scene, Mannequin::getClassTypeId());
  for (int i = 0; i < mannequins.getLength(); ++i)
    static_cast<Mannequin*>(mannequins[i]->getTail())->showVolumes = TRUE;
}

// --display-subdivision: every ClothingLayer draws `levels` of display mesh.
void useDisplaySubdivision(SoNode* scene, int levels) {
  const SoPathList layers = figment::findAll(scene, ClothingLayer::getClassTypeId());
  for (int i = 0; i < layers.getLength(); ++i)
    static_cast<ClothingLayer*>(layers[i]->getTail())->displaySubdivision = levels;
}

// --stop-at: every drape stops after `steps` steps, if not at rest before (to show a
// progressive drape's growth, say).
void stopAt(SoNode* scene, int steps) {
  for (ClothEngine* engine : figment::findClothEngines(scene))
    engine->maxTime = std::min(engine->maxTime.getValue(), steps * engine->timeStepSeconds());
}

// --frames: every drape runs at least to the last frame's time (a cloth at rest before
// then stops there, and its later frames show it at rest).
void simulateUntil(const std::vector<ClothEngine*>& engines, double seconds) {
  for (ClothEngine* engine : engines)
    if (engine->maxTime.getValue() < seconds) engine->maxTime = seconds;
}

// Finished drapes are kept in the user's cache folder (none without one).
void useDrapeCache(SceneSession& session, bool use) {
  const std::filesystem::path folder = figment::DrapeCache::userFolder();
  if (use && !folder.empty()) session.context().cache = std::make_shared<figment::DrapeCache>(folder, kCacheBytes);
}

// Drapes every engine; its errors come before any image. "" or the first error.
std::string drapeAll(SceneSession& session, const std::string& scene) {
  figment::viewer::ProgressBar bar(stderr);
  // A bar moves a few times a second; the lines of a log once a second.
  figment::DrapeContext& context = session.context();
  context.progress = [&bar](const ClothEngine& engine, const ClothEngine::Progress& p) {
    reportProgress(bar, engine, p);
  };
  context.progressInterval = bar.shown() ? 0.2 : 1.0;
  const std::vector<ClothEngine*>& engines = session.drape();
  context.progress = {};
  bar.clear();
  for (const ClothEngine* engine : engines)
    if (!engine->lastError().empty()) return engine->lastError();
  // The guard's check of the draped shapes: its error is the one line, before any verdict.
  if (!session.shapeError().empty()) return session.shapeError();
  for (const ClothEngine* engine : engines) reportFinished(scene, *engine);
  for (ClothEngine* engine : engines)  // the cache's trouble is said, not fatal
    if (!engine->lastCacheMessage().empty())
      std::fprintf(stderr, "figment-view: %s: %s\n", engine->label().c_str(), engine->lastCacheMessage().c_str());
  return "";
}

// Renders the staged root and writes it to `path`; "" or the error, with where it
// happened in `where`.
std::string renderImage(SoSeparator* root, const Options& options, SceneRenderer& renderer, const std::string& path,
                        double& renderWall, std::string& where) {
  figment::viewer::DepthBufferOnly plain(root);
  plain.use(options.depthBufferOnly);
  const auto start = std::chrono::steady_clock::now();
  std::string error = renderer.render(root, options.keepStencilFields);
  renderWall += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  where = options.scene;
  if (!error.empty()) return error;
  where = path;
  return renderer.writePng(path);
}

// Shows frame k of every engine the recorder observed.
void showFrame(const SceneSession& session, const DrapeRecorder& recorder, size_t k) {
  for (ClothEngine* engine : session.engines())
    if (recorder.observed(*engine)) figment::session::showPositions(*engine, recorder.frame(*engine, k));
}

// --fit-map: the face sets each garment's map is drawn with, coloured again at each frame
// of --frames by that frame's drape.
struct DrawnFitMap {
  const figment::session::EngineFit* fit = nullptr;
  std::vector<SoIndexedFaceSet*> faces;
};
struct DrawnFitMaps {
  figment::FitMapKind kind = figment::FitMapKind::Stretch;
  std::vector<DrawnFitMap> drawn;
};

// Colours each fit map by its garment's state at frame k (a drape not recorded step by
// step keeps its end's colours, as it shows its end).
void colourFrame(const DrawnFitMaps& maps, const DrapeRecorder& recorder, size_t k) {
  for (const DrawnFitMap& map : maps.drawn) {
    if (!recorder.observed(*map.fit->engine)) continue;
    const std::vector<int> bands = figment::session::fitMapBands(*map.fit, recorder.frame(*map.fit->engine, k),
                                                                 recorder.frameTimes()[k], maps.kind);
    for (SoIndexedFaceSet* faces : map.faces) figment::session::colourFitMap(faces, bands);
  }
}

// Frames of a time span, one camera for all: it frames the box that holds every frame.
std::string renderFrames(SceneSession& session, const DrapeRecorder& recorder, const ImagePlan& plan,
                         const Options& options, const DrawnFitMaps& maps, WrittenImages& images, double& renderWall,
                         std::string& where) {
  for (ClothEngine* engine : session.engines())  // simulated, but not step by step
    if (!recorder.observed(*engine) && engine->evaluationCount() > 0)
      std::fprintf(stderr,
                   "figment-view: %s: a progressive drape is not recorded step by step; every frame shows "
                   "its end\n",
                   engine->label().c_str());
  SbBox3f box;
  for (size_t k = 0; k < plan.frameTimes.size(); ++k) {
    showFrame(session, recorder, k);
    box.extendBy(figment::session::sceneBox(session.scene(), plan.size));
  }
  SoSeparator* root = session.stage(plan.size, plan.views.front(), box);
  SceneRenderer renderer(plan.size, options.supersample);
  for (size_t k = 0; k < plan.frameTimes.size(); ++k) {
    showFrame(session, recorder, k);
    colourFrame(maps, recorder, k);
    const std::string error = renderImage(root, options, renderer, plan.paths[k], renderWall, where);
    if (!error.empty()) return error;
    images.add(plan.paths[k]);
  }
  return "";
}

// The camera distance every view of a turntable keeps: the largest that framing the
// scene's box from each of them needs.
float sharedDistance(const ImagePlan& plan, const SbBox3f& box) {
  const float aspect = float(plan.size.width) / float(plan.size.height);
  float distance = 0.0f;
  for (const std::optional<figment::session::ViewDirection>& view : plan.views)
    distance = std::max(
        distance, figment::session::framingDistance(box, view.value_or(figment::session::ViewDirection{}), aspect));
  return distance;
}

// One image per view of the drape; a turntable's views from one distance.
std::string renderViews(SceneSession& session, const ImagePlan& plan, const Options& options, WrittenImages& images,
                        double& renderWall, std::string& where) {
  SceneRenderer renderer(plan.size, options.supersample);
  SbBox3f box;
  float distance = 0.0f;  // each view frames the scene itself
  if (plan.oneDistance) {
    box = figment::session::sceneBox(session.scene(), plan.size);
    distance = sharedDistance(plan, box);
  }
  for (size_t i = 0; i < plan.views.size(); ++i) {
    SoSeparator* root = distance > 0.0f ? session.stage(plan.size, plan.views[i], box, distance)
                                        : session.stage(plan.size, plan.views[i]);
    const std::string error = renderImage(root, options, renderer, plan.paths[i], renderWall, where);
    if (!error.empty()) return error;
    images.add(plan.paths[i]);
  }
  return "";
}

// --export: the drape as it ended (before any frame is shown), its files kept for removal
// should a later step fail.
std::string exportDrape(const SceneSession& session, const Options& options, WrittenImages& outputs) {
  std::vector<std::string> written;
  const std::string error =
      figment::session::exportScene(session.scene(), {options.exportBody}, options.exportPath, &written);
  for (std::string& path : written) outputs.add(std::move(path));
  return error;
}

// The garments' fit on their bodies, for the fit map's colours and the statistics; the
// statistics' verdicts judge against chart bodies made with MakeHuman's data, read only then.
std::vector<figment::session::EngineFit> measureFits(const SceneSession& session, const Options& options) {
  using figment::session::measureEngineFits;
  if (options.fitMap.empty() && options.stats.empty()) return {};
  if (options.stats.empty()) return measureEngineFits(session.scene(), false, nullptr);
  figment::MakeHumanLibrary makeHuman;
  return measureEngineFits(session.scene(), true, &makeHuman);
}

int render(const Options& options, const std::optional<ImagePlan>& images) {
  using namespace figment::session;
  using namespace figment::viewer;
  const ImagePlan plan = images.value_or(ImagePlan{});  // no -o: an export alone
  figment::initHeadless();
  SceneSession session;
  if (!session.load(options.scene)) return fail(options.scene, session.loadError());
  if (options.showVolumes) showVolumes(session.scene());
  if (options.displaySubdivision >= 0) useDisplaySubdivision(session.scene(), options.displaySubdivision);
  if (!plan.frameTimes.empty()) simulateUntil(session.engines(), plan.frameTimes.back());
  if (options.stopAt > 0) stopAt(session.scene(), options.stopAt);
  useDrapeCache(session, !options.noCache);
  // Frames and the wind force are recorded while the engines drape (and are then
  // simulated, neither read from nor kept in the drape cache).
  std::unique_ptr<DrapeRecorder> recorder;
  if (!plan.frameTimes.empty() || !options.windForce.empty())
    recorder = std::make_unique<DrapeRecorder>(session.sharedContext(), plan.frameTimes,
                                               options.windForce.empty() ? 0.0 : kWindSampleSpacing);
  // The engines' errors and the guard's check of the draped shapes (nothing is staged
  // past it) come before any verdict line.
  std::string error = drapeAll(session, options.scene);
  if (!error.empty()) return fail(options.scene, error);
  // --strict: a drape that is not clean (its line said above) is an error; nothing is written.
  if (options.strict && !session.verdicts().empty()) return 1;

  // The garments' fit on their bodies: for the fit map's colours and the statistics.
  const std::vector<figment::session::EngineFit> fits = measureFits(session, options);
  if (!options.fitMap.empty() && fits.empty())
    return fail("--fit-map " + options.fitMap,
                "no garment drawn by a ClothingLayer on a mesh body (a HumanBody or MeshFile) to colour");

  WrittenImages outputs;
  if (!options.exportPath.empty()) {
    error = exportDrape(session, options, outputs);
    if (!error.empty()) return fail("--export " + options.exportPath, error);
  }
  // After the export: it keeps the garments' own colours.
  DrawnFitMaps maps;
  if (!options.fitMap.empty()) maps.kind = figment::fitMapKind(options.fitMap);
  for (const EngineFit& fit : fits)
    if (!options.fitMap.empty()) maps.drawn.push_back({&fit, drawFitMap(fit, fitMapBands(fit, maps.kind))});
  double renderWall = 0.0;
  std::string where;
  if (images)
    error = plan.frameTimes.empty() ? renderViews(session, plan, options, outputs, renderWall, where)
                                    : renderFrames(session, *recorder, plan, options, maps, outputs, renderWall, where);
  if (!error.empty()) return fail(where, error);
  if (!options.windForce.empty()) {
    error = writeWindForceCsv(options.windForce, session.engines(), *recorder);
    if (!error.empty()) return fail(options.windForce, error);
  }
  if (!options.stats.empty()) {
    error = writeStatsJson(options.stats, options.scene, session.engines(), fits, renderWall, plan.size);
    if (!error.empty()) return fail(options.stats, error);
  }
  outputs.keep();
  return 0;
}

// --list-nodes: the types figment::init() adds to Coin's, with their fields.
int listNodes() {
  SoDB::init();
  std::cout << figment::viewer::describeTypes(figment::viewer::typesAddedBy([] { figment::init(); }));
  return std::cout.flush() ? 0 : 1;
}

// An exception's message as one line.
std::string oneLine(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

// The options that say which images and files come out: scene, views, frames, outputs.
void describeOutputOptions(CLI::App& app, Options& options) {
  // Not required by CLI11: --list-nodes needs neither (checked below).
  app.add_option("scene", options.scene, "Scene file (.iv)");
  app.add_option(
      "-o,--output", options.output,
      "PNG image to write. Several images (--view repeated, --turntable, --frames) are numbered "
      "from 0 before the extension, zero-padded to the largest number's width so they sort: -o out.png gives "
      "out-0.png ... out-7.png for 8 images, out-00.png ... out-39.png for 40; a %d or %0Nd in the name (N 1 to 9) "
      "takes the number instead: -o frame-%03d.png gives frame-000.png, ...");
  app.add_option("--size", options.size, "Image size in pixels, WxH")->capture_default_str();
  app.add_option("--view", options.views,
                 "Camera direction: front, back, left, right or AZ,EL in degrees (default: the scene's camera, "
                 "else front). Repeat it for several images of the one drape, in the order given")
      ->allow_extra_args(false);
  app.add_option("--turntable", options.turntable,
                 "N images around the body: azimuths 0, 360/N, 2*360/N, ... degrees at elevation 0 (with one "
                 "--view AZ,EL: from AZ, at EL), all from one camera distance, so the figure keeps its size");
  app.add_option("--frames", options.frames,
                 "T0:T1:N: the drape's state at N simulated times from T0 to T1 seconds, evenly spaced (both "
                 "included), one image each, from one camera framing them all; the drape runs to T1 at least "
                 "(a cloth at rest before then shows its rest). Drapes are simulated, neither read from nor kept "
                 "in the drape cache. One view");
  app.add_option("--wind-force", options.windForce,
                 "Write the wind's total force on each garment over simulated time here (CSV: engine, time_s, "
                 "pressure_Pa, phase_rad, force_x_N, force_y_N, force_z_N, force_N; every 5 ms simulated). Drapes are "
                 "simulated, neither read from nor kept in the drape cache");
  app.add_option("--stats", options.stats,
                 "Write simulation and render statistics (JSON) here; each garment on a measurable body (a "
                 "HumanBody, posed or standing, a human body read from a file) with its fit per region "
                 "(docs/sizes.md), and a catalogue garment's verdicts against its size on its own chart body");
  app.add_option("--fit-map", options.fitMap,
                 "Draw the draped garments on mesh bodies in their fit map's colours (docs/sizes.md): stretch "
                 "(blue at rest to red at the fabric's limit), ease (red on the skin to blue 5 cm off) or pressure "
                 "(blue at 0 to red at 2 kPa), eight bands; with --frames, each frame in its own drape's colours")
      ->check(CLI::IsMember({"stretch", "ease", "pressure"}));
  app.add_option("--export", options.exportPath,
                 "After draping, write the draped garments here, one mesh each with its Material's diffuse colour "
                 "and smooth normals, in metres, y up: .glb or .gltf (glTF 2.0; a .gltf gets its .bin beside it) or "
                 ".obj (with its .mtl). Written whole or not at all. With it, -o is optional");
  app.add_flag("--export-body", options.exportBody,
               "With --export: the body too (every other shape the scene draws, one mesh each)");
}

// The command line: every option, its help and the examples of --help.
void describeOptions(CLI::App& app, Options& options) {
  describeOutputOptions(app, options);
  app.add_flag("--depth-buffer-only", options.depthBufferOnly,
               "Draw ClothingLayer, DepthSortedGroup and StencilSeparator as IndexedFaceSet, Group and "
               "Separator: the depth buffer alone, to compare with the hybrid rendering");
  app.add_flag("--keep-stencil-fields", options.keepStencilFields,
               "Render with the scene's StencilSeparator.writeStencil and ClothingLayer.masked values, "
               "not those the stencil rule sets for the camera");
  app.add_option("--supersample", options.supersample,
                 "Anti-aliasing: draw each image at K times its width and height and average each K x K block "
                 "into one pixel (1: none, every pixel one sample). Lowered where K times --size would pass "
                 "the largest image the off-screen context draws")
      ->check(CLI::Range(1, 8))
      ->capture_default_str();
  app.add_option("--display-subdivision", options.displaySubdivision,
                 "Draw every ClothingLayer with N levels of display mesh (its displaySubdivision: each triangle "
                 "split in four N times, smooth; 0: the simulation's faces)")
      ->check(CLI::Range(0, ClothingLayer::kMostDisplaySubdivision));
  app.add_option("--stop-at", options.stopAt, "Stop every drape after this many steps (if not at rest before)")
      ->check(CLI::PositiveNumber);
  app.add_flag("--strict", options.strict,
               "A drape that is not clean (not at rest at maxTime, an edge torn past 1.5 times its rest length, a "
               "limiter acting at the end, a failed implicit step: each said in one line) is an error: exit 1, "
               "no image or export");
  app.add_flag("--show-volumes", options.showVolumes,
               "Draw every Mannequin's collision volumes as wireframes over the body");
  app.add_flag("--no-cache", options.noCache,
               "Drape even where the drape cache ($XDG_CACHE_HOME/figment, else ~/.cache/figment) holds this "
               "drape, and keep nothing there");
  app.add_flag("--list-nodes", options.listNodes,
               "Print FIGMENT's node and engine types with each field's type and default value (from Coin's "
               "field data), and exit");
  app.footer(
      "A long drape draws a progress bar on stderr when stderr is a terminal (a line a second otherwise).\n"
      "Examples:\n"
      "  figment-view scenes/dress.iv -o dress.png --view front --view 30,10 --view back  (dress-0/1/2.png)\n"
      "  figment-view scenes/dress.iv -o turn.png --turntable 8 --view 0,10               (turn-0 ... turn-7.png)\n"
      "  figment-view scenes/dress.iv --export dress.glb --export-body                    (the drape for Blender)\n"
      "  figment-view scenes/wind.iv -o wind/frame.png --frames 0.5:4.4:40 --wind-force wind.csv");
}

int run(int argc, char** argv, Options& options) {
  CLI::App app{
      "figment-view: renders a FIGMENT scene (.iv) to PNG images, headless. The scene drapes once, "
      "however many images it gives; each image is written whole or not at all, and on an error none "
      "is left."};
  describeOptions(app, options);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return fail("usage", std::string(e.what()) + " (see --help)", 2);
  }
  if (options.listNodes) return listNodes();
  if (options.scene.empty()) return fail("usage", "scene is required (see --help)", 2);
  if (options.output.empty() && options.exportPath.empty())
    return fail("usage", "--output or --export is required (see --help)", 2);
  if (options.exportBody && options.exportPath.empty())
    return fail("usage", "--export-body needs --export (see --help)", 2);
  if (!options.exportPath.empty() && !figment::meshSetFormatOf(options.exportPath))
    return fail("--export " + options.exportPath, "unknown extension (.glb, .gltf or .obj)", 2);
  if (options.output.empty()) return render(options, std::nullopt);

  figment::viewer::ImageOptionError error;
  const std::optional<ImagePlan> plan = figment::viewer::planImages(
      {options.output, options.size, options.views, options.turntable, options.frames}, error);
  return plan ? render(options, plan) : fail(error.option, error.message, 2);
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
