#include "viewer/StatsJson.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/AtomicFile.h"

namespace figment::viewer {

namespace {
// How the drape was integrated (the method that ran: with a tolerance, the picked one)
// and how often the paper's stability measures engaged.
nlohmann::json method(const session::EngineDrape& drape) {
  const session::DrapeMethod& m = drape.method;
  const bool limited = m.accelerationLimiter != "NONE";
  return {{"integrator", m.integrator},
          {"time_step_s", m.timeStep},
          {"max_time_s", m.maxTime},
          {"contact_model", m.contactModel},
          {"strain_limit", m.strainLimit},
          {"clamped_section_share", drape.run.clampedSectionShare},
          {"acceleration_limiter", m.accelerationLimiter},
          {"acceleration_limit_g", limited ? m.accelerationLimit : 0.0},
          {"limited_node_share", drape.run.limitedNodeShare}};
}
// How the drape ended (ClothEngine::RunStats): its verdict ("" when clean) and the
// figures it is made of.
nlohmann::json verdict(const ClothEngine::RunStats& run) {
  return {{"clean", run.verdict.empty()},
          {"text", run.verdict},
          {"max_speed_m_s", run.maxSpeed},
          {"max_edge_stretch", run.maxStretch},
          {"clamped_section_share_at_end", run.clampedSectionShareAtEnd},
          {"limited_node_share_at_end", run.limitedNodeShareAtEnd},
          {"halved_steps", run.halvedSteps},
          {"failed_steps", run.failedSteps}};
}
// What the garment collided with: its kind (mesh, mannequin or none) and its parts.
nlohmann::json body(const CollisionBody::Description& description) {
  nlohmann::json out = {{"kind", description.kind}};
  for (const auto& [name, count] : description.counts) out[name] = count;
  return out;
}
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

std::string writeStatsJson(const std::string& path, const std::string& scene,
                           const std::vector<session::EngineDrape>& drapes, const std::vector<session::EngineFit>& fits,
                           double renderWallSeconds, const ImageSize& size) {
  nlohmann::json garments = nlohmann::json::array();
  for (const session::EngineDrape& drape : drapes) {
    const ClothEngine::RunStats& run = drape.run;
    nlohmann::json garment = {{"name", drape.name},           {"triangles", run.triangles},
                              {"iterations", run.iterations}, {"simulated_s", run.simulatedSeconds},
                              {"wall_s", run.wallSeconds},    {"at_rest", run.atRest},
                              {"verdict", verdict(run)},      {"cached", run.fromCache},
                              {"method", method(drape)},      {"body", body(drape.body)}};
    // With a tolerance: what the engine picked and the deviation measured for it.
    if (!run.picked.empty())
      garment["picked"] = {{"configuration", run.picked},
                           {"measured_worst_mean_dev_pct_height", run.pickedDeviation},
                           {"passed_over", run.passedOver}};
    // A progressive drape (paper §4): the level it reached, of how many, and its sections.
    // When the end level arrived and how far the garment moved after it (m).
    if (run.levels > 0)
      garment["progressive"] = {{"level", run.level},
                                {"levels", run.levels},
                                {"sections", run.sections},
                                {"end_level_s", run.endLevelSeconds},
                                {"moved_after_end_level_mean_m", run.meanMoveAfterEndLevel},
                                {"moved_after_end_level_max_m", run.maxMoveAfterEndLevel}};
    for (const session::EngineFit& fit : fits)
      if (fit.engine == drape.engine && !fit.regions.empty()) garment["fit"] = fitJson(fit);
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
