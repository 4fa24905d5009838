#pragma once
// What each engine's simulation passed through on its way (figment-view --frames and
// --wind-force), recorded by the step observer of a drape context while the session
// drapes: the garment's positions at chosen simulated times, and the wind's total force.

#include <Inventor/SbVec3f.h>

#include <map>
#include <memory>
#include <vector>

#include "nodes/cloth/ClothEngine.h"
#include "nodes/cloth/DrapeContext.h"
#include "sim/core/TriangleMesh.h"

namespace figment::session {

// The wind on a whole garment at one moment (paper §2, Fig. 2.2; sim/cloth/Wind.h).
struct WindSample {
  double time = 0.0;          // s simulated
  double pressure = 0.0;      // Pa, p(t)
  double phase = 0.0;         // rad, phi(t): the phase after the last random change
  Vec3 force = Vec3::Zero();  // N, the sum over the sections of p(t) A |n . w| w
};

class DrapeRecorder {
 public:
  // Records each engine's positions at `frameTimes` (s, ascending) and, when
  // `windSpacing` > 0, the wind force about every `windSpacing` seconds simulated (at
  // most once a step). Observes every engine that drapes with `context` (a session's:
  // SceneSession::sharedContext) until destroyed, as its step observer.
  DrapeRecorder(std::shared_ptr<DrapeContext> context, std::vector<double> frameTimes, double windSpacing);
  ~DrapeRecorder();
  DrapeRecorder(const DrapeRecorder&) = delete;
  DrapeRecorder& operator=(const DrapeRecorder&) = delete;

  const std::vector<double>& frameTimes() const { return frameTimes_; }
  // Whether the engine's last simulation was observed (not a progressive drape).
  bool observed(const ClothEngine& engine) const;
  // The engine's positions at frame `k`: the state at the first step at or after the
  // frame's time; a frame after its run ended (at rest or at maxTime) holds the run's
  // last state. Empty when the engine was not observed.
  std::vector<SbVec3f> frame(const ClothEngine& engine, size_t k) const;
  // The engine's wind samples, in time order; empty without wind or observation.
  const std::vector<WindSample>& windSamples(const ClothEngine& engine) const;

 private:
  struct Record {
    std::vector<std::vector<SbVec3f>> frames;  // those reached so far
    std::vector<SbVec3f> last;                 // the last state observed
    std::vector<WindSample> wind;
    double nextWindTime = 0.0;
  };
  void observe(const ClothEngine& engine, const ClothSolver& solver);

  std::shared_ptr<DrapeContext> context_;
  std::vector<double> frameTimes_;
  double windSpacing_;
  std::map<const ClothEngine*, Record> records_;
};

}  // namespace figment::session
