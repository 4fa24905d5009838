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
nlohmann::json method(const DrapeReport& report) {
  const DrapeMethod& m = report.method;
  const bool limited = m.limiter != AccelerationLimiter::None;
  return {{"integrator", fieldName(m.integrator)},
          {"time_step_s", m.timeStep},
          {"max_time_s", report.maxTime},
          {"contact_model", fieldName(m.contacts)},
          {"strain_limit", report.strainLimit},
          {"clamped_section_share", report.run.clampedSectionShare},
          {"acceleration_limiter", fieldName(m.limiter)},
          {"acceleration_limit_g", limited ? m.limit.value_or(0.0) : 0.0},
          {"limited_node_share", report.run.limitedNodeShare}};
}
// How the drape ended (DrapeReport): its verdict ("" when clean) and the
// figures it is made of.
nlohmann::json verdict(const DrapeReport& report) {
  return {{"clean", report.verdict.empty()},
          {"text", report.verdict},
          {"max_speed_m_s", report.run.maxSpeed},
          {"max_edge_stretch", report.run.maxStretch},
          {"clamped_section_share_at_end", report.run.clampedSectionShareAtEnd},
          {"limited_node_share_at_end", report.run.limitedNodeShareAtEnd},
          {"halved_steps", report.run.implicitCosts.halvedSteps},
          {"failed_steps", report.run.implicitCosts.failedSteps}};
}
// What the garment collided with: its kind (mesh, mannequin or none) and its parts.
nlohmann::json body(const BodyDescription& description) {
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
    const DrapeReport& report = drape.report;
    nlohmann::json garment = {{"name", drape.name},
                              {"triangles", report.triangles},
                              {"iterations", report.run.iterations},
                              {"simulated_s", report.run.simulatedTime},
                              {"wall_s", report.wallSeconds},
                              {"at_rest", report.run.atRest},
                              {"verdict", verdict(report)},
                              {"cached", report.fromCache},
                              {"method", method(report)},
                              {"body", body(report.body)}};
    // With a tolerance: what the engine picked and the deviation measured for it.
    if (!report.picked.empty())
      garment["picked"] = {{"configuration", report.picked},
                           {"measured_worst_mean_dev_pct_height", report.pickedDeviation},
                           {"passed_over", report.passedOver}};
    // A progressive drape (paper §4): the level it reached, of how many, and its sections.
    // When the end level arrived and how far the garment moved after it (m).
    if (report.levels > 0)
      garment["progressive"] = {{"level", report.level},
                                {"levels", report.levels},
                                {"sections", report.sections},
                                {"end_level_s", report.settling.arrival},
                                {"moved_after_end_level_mean_m", report.settling.meanMove},
                                {"moved_after_end_level_max_m", report.settling.maxMove}};
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
