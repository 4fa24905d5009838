#include "RenderStudy.h"

#include <Inventor/SoPath.h>
#include <Inventor/actions/SoGetPrimitiveCountAction.h>
#include <Inventor/lists/SoPathList.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>

#include "CsvFile.h"
#include "Statistics.h"
#include "nodes/SceneSearch.h"
#include "nodes/render/ClothingLayer.h"
#include "session/SceneRenderer.h"
#include "session/SceneSession.h"
#include "session/SceneStaging.h"
#include "viewer/DepthBufferOnly.h"

namespace figment::bench {

namespace {

using Clock = std::chrono::steady_clock;
// (mode, view) -> milliseconds per render
using Timings = std::map<std::pair<std::string, std::string>, std::vector<double>>;
constexpr int kRounds = 8;  // hybrid and plain alternate, so drift on the machine hits both

int countTriangles(SoNode* root, SoType type) {
  int triangles = 0;
  const SoPathList paths = findAll(root, type);
  for (int i = 0; i < paths.getLength(); ++i) {
    SoGetPrimitiveCountAction count;
    count.apply(paths[i]);
    triangles += count.getTriangleCount();
  }
  return triangles;
}

// The staged camera, pointed at the scene from an azimuth, 10 degrees up.
class Orbit {
 public:
  Orbit(const session::SceneSession& session, const session::ImageSize& size)
      : box_(session.stagedBox()), aspect_(float(size.width) / float(size.height)) {
    const SoPathList cameras = findAll(session.stagedRoot(), SoPerspectiveCamera::getClassTypeId());
    camera_ = static_cast<SoPerspectiveCamera*>(cameras[0]->getTail());
  }
  void look(double azimuth) {
    SoPerspectiveCamera* framing = session::framingCamera(box_, session::ViewDirection{azimuth, 10.0}, aspect_);
    framing->ref();
    camera_->copyFieldValues(framing);
    framing->unref();
  }

 private:
  SbBox3f box_;
  float aspect_;
  SoPerspectiveCamera* camera_;
};

// Renders the staged scene in rounds, hybrid and plain alternating. False when there is
// no off-screen context to render with.
bool timeRenders(const session::SceneSession& session, const RenderStudyOptions& options, Timings& ms) {
  const session::ImageSize size{options.width, options.height};
  SoSeparator* root = session.stagedRoot();
  Orbit orbit(session, size);
  session::SceneRenderer renderer(size);
  viewer::DepthBufferOnly swaps(root);
  const int perRound = std::max(1, options.repeat / kRounds);
  for (int round = 0; round < kRounds; ++round)
    for (const char* mode : {"hybrid", "plain"}) {
      swaps.use(std::string(mode) == "plain");
      orbit.look(30.0);
      // The first render after a switch: what a single snapshot pays (no cache yet).
      const auto first = Clock::now();
      if (!renderer.render(root).empty()) return false;
      ms[{mode, "first"}].push_back(std::chrono::duration<double, std::milli>(Clock::now() - first).count());
      for (const char* view : {"still", "orbit"})
        for (int i = 0; i < perRound; ++i) {
          // still: the same camera every frame; orbit: a new azimuth every frame.
          orbit.look(std::string(view) == "still" ? 30.0
                                                  : 30.0 + 360.0 * (round * perRound + i) / (kRounds * perRound));
          const auto start = Clock::now();
          renderer.render(root);
          ms[{mode, view}].push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
        }
    }
  swaps.use(false);
  return true;
}

// The CSV rows and the printed summary of one scene.
void report(const std::string& scenePath, const session::ImageSize& size, int cloth, Timings& ms, std::ostream& csv) {
  for (const char* view : {"first", "still", "orbit"}) {
    const double hybrid = median(ms[{"hybrid", view}]), plain = median(ms[{"plain", view}]);
    const double overhead = 100.0 * (hybrid / plain - 1.0);
    for (const auto& [mode, m] : {std::pair<const char*, double>{"hybrid", hybrid}, {"plain", plain}})
      csv << scenePath << ',' << mode << ',' << view << ',' << size.width << ',' << size.height << ',' << cloth << ','
          << ms[{mode, view}].size() << ',' << m << ',' << (std::string(mode) == "hybrid" ? overhead : 0.0) << '\n';
    std::printf("%-30s %6d cloth triangles  %-5s  hybrid %6.2f ms  plain %6.2f ms  overhead %+5.1f %%\n",
                scenePath.c_str(), cloth, view, hybrid, plain, overhead);
  }
}

// Loads, drapes, stages and times one scene; "" or what to print after "figment-bench: ".
std::string studyScene(const std::string& scenePath, const RenderStudyOptions& options, std::ostream& csv) {
  session::SceneSession session;
  if (!session.load(scenePath)) return scenePath + ": " + session.loadError();
  // A drape's error, or a shape the guard refuses to draw (SceneSession::shapeError()).
  session.drape();
  if (const std::string error = session.firstError(); !error.empty()) return scenePath + ": " + error;
  const session::ImageSize size{options.width, options.height};
  session.stage(size, session::ViewDirection{30.0, 10.0});
  const int cloth = countTriangles(session.stagedRoot(), ClothingLayer::getClassTypeId());
  Timings ms;
  if (!timeRenders(session, options, ms)) return "cannot render (no off-screen context)";
  report(scenePath, size, cloth, ms, csv);
  return "";
}

}  // namespace

int runRenderStudy(const RenderStudyOptions& options) {
  std::filesystem::create_directories(options.outDir);
  const bool written = writeCsv(options.outDir + "/render.csv", [&](std::ostream& csv) -> std::string {
    csv << "scene,mode,view,width,height,cloth_triangles,renders,median_ms,overhead_pct\n";
    for (const std::string& scenePath : options.scenes) {
      const std::string error = studyScene(scenePath, options, csv);
      if (!error.empty()) return error;
    }
    return "";
  });
  if (!written) return 1;
  return 0;
}

}  // namespace figment::bench
