#pragma once
// The studies' command-line methods and schedules: a method is sim/drape/DrapeMethod.h's
// INTEGRATOR[+CONTACTS]:DT[:LIMITER:LIMIT_G] ("heun:1.5e-4:clamp:30", "implicit+penalty:0.05"),
// kept with the text as given; a schedule sim/drape/MethodTable.h's BEGIN_SHARE:RATE.

#include <functional>
#include <string>

#include "nodes/cloth/ClothEngine.h"
#include "sim/drape/DrapeMethod.h"

namespace figment::bench {

struct Method {
  std::string text;  // as given
  DrapeMethod drape;
};

// Throws std::invalid_argument naming the text.
Method parseMethod(const std::string& text);

// Sets the engine's method fields (integrator, contactModel, accelerationLimiter, timeStep
// and, when the method gives one, accelerationLimit).
void configure(ClothEngine& engine, const Method& m);

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
