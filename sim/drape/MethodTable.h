#pragma once
// The measured front of the speed-against-accuracy study, as plain data (io/TradeoffTable.h
// reads it from its file): each configuration that came to rest whole on every garment
// studied, with its worst mean deviation from the converged reference over those garments
// and its total wall time, only those no other configuration beats on both. A drape with a
// tolerance goes by the fastest one within it that its body allows (sim/drape/MethodChoice.h).

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sim/drape/DrapeMethod.h"

namespace figment {

struct MeasuredConfiguration {
  std::string method;       // DrapeMethod's spelling: "implicit:0.05"
  std::string body;         // volumes, capsules, triangles or mix
  std::string progressive;  // off, or BEGIN_SHARE:RATE (parseScheduleText)
  double resolution = 1.0;
  int garments = 0;
  double worstMeanDeviation = 0.0;  // % of a garment's height
  double totalWall = 0.0;           // s, over the garments

  std::string label() const;  // "implicit:0.05, triangles, progressive off"
};

struct MethodTable {
  std::string source;  // where it was read, for messages
  std::vector<MeasuredConfiguration> configurations;
};

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

}  // namespace figment
