#include "viewer/StatsJson.h"

#include "nodes/ClothEngine.h"
#include "viewer/AtomicFile.h"

#include <nlohmann/json.hpp>

#include <fstream>

namespace figment::viewer {

std::string writeStatsJson(const std::string& path, const std::string& scene,
                           const std::vector<ClothEngine*>& engines, double renderWallSeconds,
                           const ImageSize& size) {
  nlohmann::json garments = nlohmann::json::array();
  for (const ClothEngine* engine : engines) {
    const ClothEngine::RunStats& run = engine->lastRun();
    garments.push_back({{"name", engine->getName().getString()},
                        {"triangles", run.triangles},
                        {"iterations", run.iterations},
                        {"simulated_s", run.simulatedSeconds},
                        {"wall_s", run.wallSeconds},
                        {"at_rest", run.atRest}});
  }
  const nlohmann::json stats = {{"scene", scene},
                                {"garments", garments},
                                {"render_wall_s", renderWallSeconds},
                                {"size", {size.width, size.height}}};
  return writeAtomically(path, [&stats](const std::string& temporary) -> std::string {
    std::ofstream out(temporary);
    out << stats.dump(2) << "\n";
    out.close();
    return out ? "" : "cannot write the file";
  });
}

}  // namespace figment::viewer
