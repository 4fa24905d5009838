#include "sim/cloth/DrapeVerdict.h"

#include <cstdio>
#include <vector>

#include "sim/core/ParameterChecks.h"

namespace figment {

namespace {
// `value` with three significant digits: figures to read, not to reproduce.
std::string figure(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}
}  // namespace

bool DrapeVerdict::tore() const {
  return run.maxStretch > kTearStretch;
}

std::string DrapeVerdict::describe() const {
  const ImplicitStepCosts& steps = run.implicitCosts;
  std::vector<std::string> parts;
  if (!run.atRest)
    parts.push_back("not at rest after maxTime " + formatNumber(maxTime) + " s (max speed " + figure(run.maxSpeed) +
                    " m/s)");
  if (tore())
    parts.push_back("torn: an edge at " + figure(run.maxStretch) + " times its rest length (bound " +
                    formatNumber(kTearStretch) + ")");
  if (run.limitedNodeShareAtEnd > 0.0)
    parts.push_back("limited: the acceleration limiter cut " + figure(100.0 * run.limitedNodeShareAtEnd) +
                    " % of the nodes in the last step");
  if (run.clampedSectionShareAtEnd > 0.0)
    parts.push_back("limited: the strain clamping held " + figure(100.0 * run.clampedSectionShareAtEnd) +
                    " % of the sections in the last step");
  if (steps.failedSteps > 0)
    parts.push_back(std::to_string(steps.failedSteps) + " implicit step" + (steps.failedSteps == 1 ? "" : "s") +
                    " still stretched an edge past " + formatNumber(kTearStretch) +
                    " at the step control's smallest step (" + std::to_string(steps.halvedSteps) + " halved)");
  std::string line;
  for (const std::string& part : parts) line += (line.empty() ? "" : "; ") + part;
  return line;
}

}  // namespace figment
