#pragma once
// The method study: one scene's garment draped by each integration method and time step,
// speed against accuracy: steps, median wall time to rest, deviation from a converged
// reference, largest strain, nodes inside the body, and where its top edge comes to rest.

#include <string>
#include <vector>

namespace figment::bench {

struct MethodStudyOptions {
  std::vector<std::string> scenes = {"scenes/dress.iv"};
  // Each "INTEGRATOR:DT[:LIMITER:LIMIT_G]" as the ClothEngine fields spell them, case
  // free: "heun:1.5e-4", "heun:1.5e-4:clamp:30", "implicit:0.01".
  std::vector<std::string> methods = {"heun:1.5e-4"};
  std::string reference = "heun:5e-5";  // what deviations are measured against
  int repeat = 5;                       // runs per method; wall time is their median
  std::string outDir = "bench-out";
};

// Writes DIR/methods.csv and prints one table per scene. Returns the exit code.
int runMethodStudy(const MethodStudyOptions& options);

}  // namespace figment::bench
