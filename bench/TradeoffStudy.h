#pragma once
// The speed-against-accuracy study: each garment draped by every combination of method
// (integrator, time step, limiter, contact model), collision body (the radial depth
// volumes, the capsules, the body's own triangles), progressive schedule and garment
// resolution, against a converged reference: the full-resolution garment on the body's
// triangles by Heun without limiters at a small step. For each configuration: median
// wall time to rest, steps, mean and largest deviation from the reference (% of the
// garment's height; another resolution is compared through its rest surface,
// RestCorrespondence.h), nodes inside the body, largest strain, and how it failed (blew
// up, tore: an edge 20 % off its rest length, never rested). Configurations that did
// not fail and that no other is both faster and closer than form the Pareto front.

#include <string>
#include <vector>

namespace figment::bench {

struct TradeoffStudyOptions {
  std::vector<std::string> scenes = {"scenes/dress.iv", "scenes/tshirt.iv", "scenes/skirt.iv"};
  // "INTEGRATOR[+CONTACTS]:DT[:LIMITER:LIMIT_G]" (MethodSpec.h).
  // The last two: the step growing from 1/20 s to 0.4 s while the cloth is quiet, as the
  // shipped scenes and the service drape.
  std::vector<std::string> methods = {"heun:1.5e-4",           "heun:1.5e-4:clamp:30", "implicit:0.01",
                                      "implicit:0.02",         "implicit:0.05",        "implicit+penalty:0.02",
                                      "implicit+penalty:0.05", "implicit:0.05:0.4",    "implicit+penalty:0.05:0.4"};
  std::vector<std::string> bodies = {"volumes", "capsules", "triangles", "mix"};
  // "off", or BEGIN_SHARE:RATE as figment-bench progressive takes them; the script is
  // made for each resolution, to `coarseShare` of its sections.
  std::vector<std::string> schedules = {"off", "0:3000"};
  double coarseShare = 0.25;
  std::vector<double> resolutions = {0.5, 1.0, 2.0};  // sections, times the garment's
  // Heun without limiters, at a step under every garment's stability bound: 5e-5 s blew up
  // on the T-shirt as its generator cuts it now (its narrowest triangle 3.7 mm high, 6.1 mm
  // before), at 0.01 s.
  std::string reference = "heun:2.5e-5";
  bool checkReference = true;  // drape the reference at half its step too: how far it moves
  int repeat = 3;              // drapes per configuration; wall time is their median
  bool quick = false;          // the default dress, a subset of the above, one drape each
  std::string volumesFile = "scenes/human-volumes.iv";
  std::string capsulesFile = "scenes/human-capsules.iv";
  std::string outDir = "bench-out";
  std::string plotScript;  // matplotlib script that charts the CSV; "" = no chart
};

// The options --quick stands for: under 5 minutes on one core.
TradeoffStudyOptions quickTradeoff(TradeoffStudyOptions options);

// Writes DIR/tradeoff.csv (a row per configuration), DIR/tradeoff-reference.csv,
// DIR/tradeoff-table.csv (the front over all garments, io/TradeoffTable.h) and, with the
// plot script, DIR/tradeoff.png. Returns the exit code.
int runTradeoffStudy(const TradeoffStudyOptions& options);

}  // namespace figment::bench
