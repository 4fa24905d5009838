// A second front end on FIGMENT's scene session: it links figment::session (with the
// example's SphereVolume and figment::io for the drape cache), none of figment-view's
// code. Two sessions share one drape context, which holds a cache in CACHE_FOLDER and a
// progress callback: the first drapes the scene, the second reads that drape from the
// cache, bit for bit. Exits 0 when both drapes succeed, the first was simulated and
// reported progress, and the second came from the cache with the same positions.
//   session_drape SCENE.iv CACHE_FOLDER

#include <Inventor/SoDB.h>
#include <Inventor/fields/SoMFVec3f.h>
#include <io/DrapeCache.h>
#include <nodes/Init.h>
#include <session/SceneSession.h>
#include <sim/drape/DrapeReport.h>

#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "SphereVolume.h"

namespace {

// The draped points where the scene's first engine feeds them; empty without one.
std::vector<SbVec3f> drapedPoints(const figment::session::SceneSession& session) {
  if (session.engines().empty() || session.engines().front()->positions.getNumConnections() == 0) return {};
  const auto* points = static_cast<const SoMFVec3f*>(session.engines().front()->positions[0]);
  return {points->getValues(0), points->getValues(0) + points->getNum()};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s SCENE.iv CACHE_FOLDER\n", argv[0]);
    return 2;
  }
  SoDB::init();
  figment::init();
  SphereVolume::initClass();

  auto context = std::make_shared<figment::DrapeContext>();
  context->cache = std::make_shared<figment::DrapeCache>(argv[2], 64u << 20);
  int reports = 0;
  context->progress = [&reports](const ClothEngine&, const ClothEngine::Progress&) { ++reports; };
  context->progressInterval = 0.0;  // every 64 steps

  std::vector<SbVec3f> points[2];
  bool cached[2] = {false, false};
  for (int i = 0; i < 2; ++i) {
    figment::session::SceneSession session(context);
    if (!session.load(argv[1])) {
      std::fprintf(stderr, "session_drape: %s: %s\n", argv[1], session.loadError().c_str());
      return 1;
    }
    const std::vector<ClothEngine*>& engines = session.drape();
    if (engines.size() != 1 || !session.firstError().empty()) {
      std::fprintf(stderr, "session_drape: %s: %zu engines; %s\n", argv[1], engines.size(),
                   session.firstError().c_str());
      return 1;
    }
    points[i] = drapedPoints(session);
    const figment::DrapeReport& report = engines.front()->lastRun();
    cached[i] = report.fromCache;
    std::printf("session %d: %s, %d steps, %zu points%s\n", i + 1, engines.front()->label().c_str(),
                report.run.iterations, points[i].size(), cached[i] ? ", from the cache" : "");
  }
  const bool same = !points[0].empty() && points[0].size() == points[1].size() &&
                    std::memcmp(points[0].data(), points[1].data(), points[0].size() * sizeof(SbVec3f)) == 0;
  std::printf("%d progress reports; the second drape %s the first\n", reports, same ? "is" : "is not");
  return !cached[0] && cached[1] && reports > 0 && same ? 0 : 1;
}
