#include "sim/drape/DrapeReport.h"

#include "sim/cloth/DrapeVerdict.h"

namespace figment {

std::string verdictOf(const DrapeReport& report) {
  const std::string ending = DrapeVerdict{report.run, report.maxTime}.describe();
  if (report.garmentWarning.empty()) return ending;
  return report.garmentWarning + (ending.empty() ? "" : "; " + ending);
}

}  // namespace figment
