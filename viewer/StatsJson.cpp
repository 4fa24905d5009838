#include "viewer/StatsJson.h"

#include "nodes/body/CapsuleVolume.h"
#include "nodes/cloth/ClothEngine.h"
#include "nodes/body/ExactVolume.h"
#include "nodes/body/Mannequin.h"
#include "nodes/body/MeshFile.h"
#include "nodes/body/RadialDepthVolume.h"
#include "io/AtomicFile.h"

#include <nlohmann/json.hpp>

#include <fstream>

namespace figment::viewer {

namespace {
// A field's value as the .iv file spells it (enum names, numbers).
std::string fieldText(const SoField& field) {
  SbString text;
  const_cast<SoField&>(field).get(text);  // Coin's get() is not const; it only reads
  return text.getString();
}

// How the drape was integrated and how often the paper's stability measures engaged.
nlohmann::json method(const ClothEngine& engine, const ClothEngine::RunStats& run) {
  const bool limited = engine.accelerationLimiter.getValue() != ClothEngine::NONE;
  return {{"integrator", fieldText(engine.integrator)},
          {"time_step_s", engine.timeStep.getValue()},
          {"strain_limit", engine.strainLimit.getValue()},
          {"clamped_section_share", run.clampedSectionShare},
          {"acceleration_limiter", fieldText(engine.accelerationLimiter)},
          {"acceleration_limit_g", limited ? engine.accelerationLimit.getValue() : 0.0},
          {"limited_node_share", run.limitedNodeShare}};
}
// What the garment collided with: a mesh (exactly), a mannequin's volumes by kind, or
// nothing.
nlohmann::json body(const ClothEngine& engine) {
  SoNode* node = engine.body.getValue();
  if (!node) return {{"kind", "none"}};
  if (!node->isOfType(Mannequin::getClassTypeId())) return {{"kind", "mesh"}};
  int capsules = 0, radial = 0, exact = 0;
  try {
    for (const Mannequin::VolumeEntry& v : static_cast<const Mannequin*>(node)->volumes()) {
      capsules += v.node->isOfType(CapsuleVolume::getClassTypeId());
      radial += v.node->isOfType(RadialDepthVolume::getClassTypeId());
      exact += v.node->isOfType(ExactVolume::getClassTypeId());
    }
  } catch (const std::exception&) {
    // An unusable mannequin fails the drape, which is reported before any stats.
  }
  return {{"kind", "mannequin"}, {"capsule_volumes", capsules}, {"radial_volumes", radial}, {"exact_parts", exact}};
}
}  // namespace

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
                        {"at_rest", run.atRest},
                        {"method", method(*engine, run)},
                        {"body", body(*engine)}});
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
