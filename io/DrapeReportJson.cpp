#include "io/DrapeReportJson.h"

#include <nlohmann/json.hpp>

namespace figment {

namespace {

// How the drape was integrated (the method that ran: with a tolerance, the picked one)
// and how often the paper's stability measures engaged.
nlohmann::json method(const DrapeReport& report) {
  const DrapeMethod& m = report.method;
  const bool limited = m.limiter != AccelerationLimiter::None;
  return {{"integrator", fieldName(m.integrator)},
          {"time_step_s", m.timeStep},
          {"max_time_step_s", m.maxTimeStep},
          {"max_time_s", report.maxTime},
          {"contact_model", fieldName(m.contacts)},
          {"strain_limit", report.strainLimit},
          {"clamped_section_share", report.run.clampedSectionShare},
          {"acceleration_limiter", fieldName(m.limiter)},
          {"acceleration_limit_g", limited ? m.limit.value_or(0.0) : 0.0},
          {"limited_node_share", report.run.limitedNodeShare}};
}

// How the drape ended: its verdict ("" when clean) and the figures it is made of.
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

}  // namespace

std::string drapeReportJson(const DrapeReport& report) {
  nlohmann::json out = {{"triangles", report.triangles},
                        {"iterations", report.run.iterations},
                        {"simulated_s", report.run.simulatedTime},
                        {"wall_s", report.wallSeconds},
                        {"at_rest", report.run.atRest},
                        {"verdict", verdict(report)},
                        {"cached", report.fromCache},
                        {"method", method(report)},
                        {"body", body(report.body)}};
  // With a tolerance: what was picked and the deviation measured for it.
  if (!report.picked.empty())
    out["picked"] = {{"configuration", report.picked},
                     {"measured_worst_mean_dev_pct_height", report.pickedDeviation},
                     {"passed_over", report.passedOver}};
  // Put on over garments already draped: how many nodes started over them (sim/drape/LayerStart.h).
  if (report.startedOverLayers > 0) out["started_over_layers"] = report.startedOverLayers;
  // A progressive drape (paper §4): the level it reached, of how many, and its sections;
  // when the end level arrived and how far the garment moved after it (m).
  if (report.levels > 0)
    out["progressive"] = {{"level", report.level},
                          {"levels", report.levels},
                          {"sections", report.sections},
                          {"end_level_s", report.settling.arrival},
                          {"moved_after_end_level_mean_m", report.settling.meanMove},
                          {"moved_after_end_level_max_m", report.settling.maxMove}};
  return out.dump();
}

}  // namespace figment
