#include "sim/drape/MethodTable.h"

#include <sstream>
#include <stdexcept>

namespace figment {

std::string MeasuredConfiguration::label() const {
  std::string out = method + ", " + body + ", progressive " + progressive;
  if (resolution != 1.0) out += ", sections x" + std::to_string(resolution);
  return out;
}

std::optional<MeasuredConfiguration> fastestWithin(const std::vector<MeasuredConfiguration>& table, double tolerance,
                                                   const std::function<bool(const MeasuredConfiguration&)>& usable) {
  std::optional<MeasuredConfiguration> best;
  for (const MeasuredConfiguration& c : table)
    if (c.worstMeanDeviation <= tolerance && usable(c) && (!best || c.totalWall < best->totalWall)) best = c;
  return best;
}

ScheduleText parseScheduleText(const std::string& text) {
  ScheduleText s;
  std::stringstream in(text);
  char colon = 0;
  if (!(in >> s.beginShare >> colon >> s.rate) || colon != ':' || !(in >> std::ws).eof() ||
      !(s.beginShare >= 0.0 && s.beginShare <= 1.0) || !(s.rate >= 0.0))
    throw std::invalid_argument("schedule \"" + text + "\": expected BEGIN_SHARE:RATE, share in [0, 1], rate >= 0");
  return s;
}

}  // namespace figment
