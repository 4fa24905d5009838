#pragma once
// DrapeContext: what a ClothEngine drapes with besides its fields, owned by the program
// (a scene session) and handed to its engines, so two sessions in one process, or a
// server's requests, never share a cache or an observer.

#include <memory>

#include "nodes/cloth/ClothEngine.h"

namespace figment {

class DrapeCache;

// Set by its owner between drapes, never while an engine that holds it evaluates. An
// engine without a context (ClothEngine::setDrapeContext, the default: a plain Coin or
// pivy program) drapes as one with a default-made context: no cache, no observers,
// the broad phase on.
struct DrapeContext {
  // Finished drapes (io/DrapeCache.h), or null (every evaluation simulates). With one,
  // an evaluation whose inputs, body, script and node library match a kept drape
  // (nodes/cloth/DrapeKey.h) reads it instead of simulating, and one that simulates
  // keeps its drape. figment-view sets one unless --no-cache.
  std::shared_ptr<const DrapeCache> cache;

  // Called with the engine and its solver once before a simulation's first step and
  // after every step (figment-view records frames and the wind force through it;
  // sim/cloth/ClothSolver.h). Whole-garment drapes only: a progressive drape's solver
  // changes with its level and is not observed. While one is set, drapes are simulated,
  // neither read from the cache (a cached drape has no steps to observe) nor kept there.
  ClothEngine::StepObserver stepObserver;

  // Called about every `progressInterval` seconds of wall time while a simulation runs
  // (looked at every 64 steps; 0: every 64 steps); figment-view draws its progress bar.
  ClothEngine::ProgressCallback progress;
  double progressInterval = 1.0;  // s

  // Whether drapes test only the body parts near the garment (sim/collision/
  // BroadPhaseCollider.h). A drape is the same either way: off only to measure what the
  // broad phase saves (figment-bench drape --broad-phase off).
  bool broadPhase = true;
};

}  // namespace figment
