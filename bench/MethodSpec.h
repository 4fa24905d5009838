#pragma once
// A drape method as the studies name it, "INTEGRATOR[+CONTACTS]:DT[:LIMITER:LIMIT_G]" in the
// ClothEngine fields' spelling (case free): "heun:1.5e-4", "heun:1.5e-4:clamp:30",
// "implicit:0.05", "implicit+penalty:0.05" (contactModel PENALTY).

#include <functional>
#include <string>

#include "nodes/cloth/ClothEngine.h"

namespace figment::bench {

struct Method {
  std::string text;  // as given
  std::string integrator, limiter = "NONE", contactModel = "CONSTRAINTS";
  double timeStep = 0.0, limit = 30.0;
};

// Throws std::invalid_argument naming the text.
Method parseMethod(const std::string& text);

// Sets the engine's method fields; "" or what is wrong.
std::string configure(ClothEngine& engine, const Method& m);

// A progressive schedule as the studies name it, "BEGIN_SHARE:RATE": the begin level as
// a share of the script's levels, splits per simulated second (0: all at once when the
// begin level rests).
struct Schedule {
  std::string text;
  double beginShare = 0.0, rate = 0.0;
};

// Throws std::invalid_argument naming the text.
Schedule parseSchedule(const std::string& text);

// Runs `parse`, which reads the command line's method and schedule texts; false, with the
// message of the std::invalid_argument it threw on stderr, when one of them is bad (the
// studies then exit with 2, CLI11's status for a bad option).
bool parsesOrReports(const std::function<void()>& parse);

}  // namespace figment::bench
