#include "RenderStudy.h"

#include "Statistics.h"
#include "nodes/render/ClothingLayer.h"
#include "nodes/SceneSearch.h"
#include "viewer/DepthBufferOnly.h"
#include "viewer/OffscreenContext.h"
#include "viewer/SceneFile.h"
#include "viewer/SceneRenderer.h"
#include "viewer/SceneStaging.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/actions/SoGetPrimitiveCountAction.h>
#include <Inventor/lists/SoPathList.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>

namespace figment::bench {

namespace {

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

}  // namespace

int runRenderStudy(const RenderStudyOptions& options) {
  using Clock = std::chrono::steady_clock;
  viewer::initHeadless();
  std::filesystem::create_directories(options.outDir);
  const std::string csvPath = options.outDir + "/render.csv";
  std::ofstream csv(csvPath + ".partial");
  csv << "scene,mode,view,width,height,cloth_triangles,renders,median_ms,overhead_pct\n";
  const viewer::ImageSize size{options.width, options.height};
  const float aspect = float(size.width) / float(size.height);
  constexpr int kRounds = 8;  // hybrid and plain alternate, so drift on the machine hits both
  for (const std::string& scenePath : options.scenes) {
    std::string error;
    SoSeparator* scene = viewer::readSceneFile(scenePath, error);
    if (!scene) {
      std::cerr << "figment-bench: " << scenePath << ": " << error << "\n";
      return 1;
    }
    scene->ref();
    SoSeparator* root = viewer::stageScene(scene, size, viewer::ViewDirection{30.0, 10.0});  // drapes
    root->ref();
    SoGetBoundingBoxAction bounds(SbViewportRegion(short(size.width), short(size.height)));
    bounds.apply(scene);
    const SbBox3f box = bounds.getBoundingBox();
    const SoPathList cameras = findAll(root, SoPerspectiveCamera::getClassTypeId());
    auto* camera = static_cast<SoPerspectiveCamera*>(cameras[0]->getTail());
    auto look = [&](double azimuth) {
      SoPerspectiveCamera* framing = viewer::framingCamera(box, viewer::ViewDirection{azimuth, 10.0}, aspect);
      framing->ref();
      camera->copyFieldValues(framing);
      framing->unref();
    };
    const int cloth = countTriangles(root, ClothingLayer::getClassTypeId());
    viewer::SceneRenderer renderer(size);
    viewer::DepthBufferOnly swaps(root);
    // (mode, view) -> milliseconds per render
    std::map<std::pair<std::string, std::string>, std::vector<double>> ms;
    const int perRound = std::max(1, options.repeat / kRounds);
    for (int round = 0; round < kRounds; ++round)
      for (const char* mode : {"hybrid", "plain"}) {
        swaps.use(std::string(mode) == "plain");
        look(30.0);
        // The first render after a switch: what a single snapshot pays (no cache yet).
        const auto first = Clock::now();
        if (!renderer.render(root).empty()) {
          std::cerr << "figment-bench: cannot render (no off-screen context)\n";
          return 1;
        }
        ms[{mode, "first"}].push_back(std::chrono::duration<double, std::milli>(Clock::now() - first).count());
        for (const char* view : {"still", "orbit"})
          for (int i = 0; i < perRound; ++i) {
            // still: the same camera every frame; orbit: a new azimuth every frame.
            look(std::string(view) == "still" ? 30.0 : 30.0 + 360.0 * (round * perRound + i) / (kRounds * perRound));
            const auto start = Clock::now();
            renderer.render(root);
            ms[{mode, view}].push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
          }
      }
    swaps.use(false);
    for (const char* view : {"first", "still", "orbit"}) {
      const double hybrid = median(ms[{"hybrid", view}]), plain = median(ms[{"plain", view}]);
      const double overhead = 100.0 * (hybrid / plain - 1.0);
      for (const auto& [mode, m] : {std::pair<const char*, double>{"hybrid", hybrid}, {"plain", plain}})
        csv << scenePath << ',' << mode << ',' << view << ',' << size.width << ',' << size.height << ',' << cloth
            << ',' << ms[{mode, view}].size() << ',' << m << ',' << (std::string(mode) == "hybrid" ? overhead : 0.0)
            << '\n';
      std::printf("%-30s %6d cloth triangles  %-5s  hybrid %6.2f ms  plain %6.2f ms  overhead %+5.1f %%\n",
                  scenePath.c_str(), cloth, view, hybrid, plain, overhead);
    }
    root->unref();
    scene->unref();
  }
  csv.close();
  std::filesystem::rename(csvPath + ".partial", csvPath);
  std::cout << csvPath << "\n";
  return 0;
}

}  // namespace figment::bench
