#pragma once
// What a finished drape says about itself, so that no front end shows a failed drape as
// if it had succeeded (figment-view prints describe() as one line per drape that is not
// clean; --strict makes it an error). A drape is clean when none of these happened:
//  - not at rest: it stopped at maxTime still moving (fastest node faster than the rest
//    speed for a whole rest window);
//  - tore: at the end an edge is longer than kTearStretch times its rest length. Woven
//    and knitted cloth breaks or lets go of its seams long before; the shipped drapes end
//    with their most stretched edge at 1.03 to 1.14 times its rest length, and every
//    drape seen torn or shredded (a sleeve pulled off a raised arm: 2.0; the default
//    dress at a 0.2 s implicit step before the step control: 2.7) past 1.5;
//  - limited: the strain clamping or the acceleration limiter (the explicit
//    integrators' stability measures) still acted in the last step, so the shape it
//    ended in is held by a limiter, not by the model's forces; one that only acted on
//    the way there leaves a clean drape;
//  - step failures: implicit steps that still stretched an edge to breaking at the step
//    control's smallest step (sim/cloth/implicit/ImplicitEuler.h). Steps the control
//    recovered by halving are reported (halvedSteps) but leave the drape clean.

#include <string>

#include "sim/cloth/DrapeResult.h"

namespace figment {

struct DrapeVerdict {
  static constexpr double kTearStretch = 1.5;  // edge length over rest length

  DrapeResult run;       // how the run ended (sim/cloth/DrapeResult.h)
  double maxTime = 0.0;  // s, the run's bound

  bool tore() const;  // an edge ended past kTearStretch
  bool limited() const { return run.clampedSectionShareAtEnd > 0.0 || run.limitedNodeShareAtEnd > 0.0; }
  bool clean() const { return run.atRest && !tore() && !limited() && run.implicitCosts.failedSteps == 0; }
  // "" when clean; else what happened, with its figures, as one line without a period:
  // "not at rest after maxTime 10 s (max speed 0.31 m/s); torn: an edge at 2.02 times its
  // rest length (bound 1.5); limited: the acceleration limiter cut 3.5 % of the nodes in
  // the last step".
  std::string describe() const;
};

}  // namespace figment
