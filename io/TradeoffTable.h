#pragma once
// The measured front of the speed-against-accuracy study (figment-bench tradeoff writes
// it, docs/tradeoff-table.csv holds the committed one, the build installs it): each
// configuration that came to rest whole on every garment studied, with its worst mean
// deviation from the converged reference over those garments and its total wall time,
// only those no other configuration beats on both. A ClothEngine with a `tolerance`
// drapes by the fastest one within it.
//
// Format: CSV with a header line; columns method, body, progressive, resolution,
// garments, worst_mean_dev_pct_height, total_median_wall_s. `method` is
// INTEGRATOR[+CONTACTS]:DT[:LIMITER:LIMIT_G] (e.g. implicit+penalty:0.05,
// heun:1.5e-4:clamp:30), body volumes/capsules/triangles, progressive off or
// BEGIN_SHARE:RATE.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sim/cloth/ClothParameters.h"

namespace figment {

struct MeasuredConfiguration {
  std::string method, body, progressive;
  double resolution = 1.0;
  int garments = 0;
  double worstMeanDeviation = 0.0;  // % of a garment's height
  double totalWall = 0.0;           // s, over the garments

  std::string label() const;  // "implicit:0.05, triangles, progressive off"
};

// Throws std::runtime_error naming the file (and line) when it cannot be read.
std::vector<MeasuredConfiguration> readTradeoffTable(const std::string& path);

// The fastest configuration within `tolerance` (% of the garment's height) among those
// `usable` accepts, if any.
std::optional<MeasuredConfiguration> fastestWithin(const std::vector<MeasuredConfiguration>& table, double tolerance,
                                                   const std::function<bool(const MeasuredConfiguration&)>& usable);

// A progressive schedule as the table spells it, "BEGIN_SHARE:RATE": the begin level as
// a share of the levels, splits per simulated second (0: all at once when the begin
// level rests). Throws std::invalid_argument naming the text.
struct ScheduleText {
  double beginShare = 0.0, rate = 0.0;
};
ScheduleText parseScheduleText(const std::string& text);

// A method as the table spells it, onto `p`'s integrator, time step, contact model and
// acceleration limiter. Throws std::invalid_argument naming the text.
void applyMethod(const std::string& method, ClothParameters& p);

}  // namespace figment
