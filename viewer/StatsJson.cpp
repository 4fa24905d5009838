#include "viewer/StatsJson.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/AtomicFile.h"
#include "io/DrapeReportJson.h"
#include "nodes/cloth/ClothEngine.h"

namespace figment::viewer {

namespace {
// A garment's fit per region (figment-size's units; girth ease -1 where not taped).
nlohmann::json fitJson(const session::EngineFit& fit) {
  nlohmann::json regions = nlohmann::json::object();
  for (size_t i = 0; i < fit.regions.size(); ++i) {
    const RegionFit& g = fit.regions[i];
    if (!g.covered()) continue;
    nlohmann::json region = {{"stretch_pct", 100 * g.meanStrain},
                             {"max_stretch_pct", 100 * g.maxStrain},
                             {"ease_mm", 1000 * g.ease},
                             {"girth_ease_cm", std::isfinite(g.girthEase) ? 100 * g.girthEase : -1.0},
                             {"pressure_kpa", g.pressure / 1000}};
    if (i < fit.verdicts.size()) region["verdict"] = verdictName(fit.verdicts[i]);
    // On a posed body, a region whose girth the pose hides: why, and no verdict on it but tight.
    if (!g.unmeasured.empty()) {
      region["unmeasured"] = g.unmeasured;
      if (i < fit.verdicts.size() && fit.verdicts[i] != Verdict::Tight) region["verdict"] = "unmeasured";
    }
    regions[g.name] = std::move(region);
  }
  return {{"catalogue", fit.garment}, {"text", fit.text}, {"regions", regions}};
}
}  // namespace

std::string writeStatsJson(const std::string& path, const std::string& scene, const std::vector<ClothEngine*>& engines,
                           const std::vector<session::EngineFit>& fits, double renderWallSeconds,
                           const ImageSize& size) {
  nlohmann::json garments = nlohmann::json::array();
  for (const ClothEngine* engine : engines) {
    nlohmann::json garment = nlohmann::json::parse(drapeReportJson(engine->lastRun()));
    garment["name"] = engine->getName().getString();
    for (const session::EngineFit& fit : fits)
      if (fit.engine == engine && !fit.regions.empty()) garment["fit"] = fitJson(fit);
    garments.push_back(std::move(garment));
  }
  const nlohmann::json stats = {{"scene", scene},
                                {"garments", garments},
                                {"render_wall_s", renderWallSeconds},
                                {"size", {size.width, size.height}}};
  return writeAtomically(path, [&stats](const std::string& temporary) -> std::string {
    std::ofstream out(temporary);
    out << stats.dump(2) << "\n";
    out.close();
    return out ? "" : std::string("cannot write the file: ") + std::strerror(errno);
  });
}

}  // namespace figment::viewer
