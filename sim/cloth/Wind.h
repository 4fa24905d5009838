#pragma once
// Wind (paper §2, Fig. 2.2): "a sinusoidally varying force of specified direction,
// amplitude, and frequency applied to the sections of the cloth while changing the
// phase of the sinusoid at random moments"; no wind shadowing.
//
//   p(t) = amplitude sin(2 pi frequency t + phi(t))                     Pa
//   phi(t) = 0 until the first phase change; each change draws a new phase uniformly
//   in [0, 2 pi). The changes form a Poisson process of mean interval
//   meanPhaseInterval: intervals dT = -meanPhaseInterval ln(1 - u), u uniform in [0, 1).
//
// The force on a section with unit normal n and area A (its current shape) is
//   F = p(t) A |n . w| w,   w = direction / |direction|                 N
// shared equally by its three corners (ClothModel). A section face-on to the wind
// catches p A; one edge-on to it (n perpendicular to w) catches none.
//
// Runs repeat on every platform: the random numbers come from std::mt19937_64 (whose
// output the standard fixes) mapped to [0, 1) here, not through the standard
// distributions, whose outputs are implementation-defined. The phase changes depend
// only on (seed, time), never on the times at which p is asked for.

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "sim/core/TriangleMesh.h"

namespace figment {

struct WindParameters {
  Vec3 direction = Vec3::UnitX();  // where the wind blows to; normalised; zero = no wind
  double amplitude = 0.0;          // Pa: force per unit section area at full face-on exposure; 0 = off
  double frequency = 1.0;          // Hz of the sinusoid
  double meanPhaseInterval = 0.5;  // s: mean time between random phase changes; 0 = never
  uint64_t seed = 1;               // of the phase changes

  // Throws std::invalid_argument naming the field (as ClothEngine names it) and value:
  // direction finite, amplitude, frequency and meanPhaseInterval >= 0.
  void validate() const;
};

// The force on each corner of the section (x0, x1, x2) at pressure p (Pa) and unit
// direction w: p A |n . w| w / 3 (N). With c = (x1 - x0) x (x2 - x0) = 2 A n,
// A |n . w| = |c . w| / 2: a section edge-on to the wind catches none.
inline Vec3 windCornerForce(const Vec3& x0, const Vec3& x1, const Vec3& x2, double pressure, const Vec3& w) {
  const Vec3 doubleAreaNormal = (x1 - x0).cross(x2 - x0);
  return (pressure * std::abs(doubleAreaNormal.dot(w)) / 6.0) * w;
}

class Wind {
 public:
  explicit Wind(const WindParameters& parameters);

  // False when the wind can exert no force (amplitude 0 or direction zero): the model
  // then skips it.
  bool blows() const { return blows_; }
  const Vec3& direction() const { return direction_; }  // unit, or zero

  // p(t), Pa, for simulated time t >= 0 s.
  double pressure(double t) const;
  // phi(t), rad in [0, 2 pi): the phase after the last change at or before t.
  double phase(double t) const;

 private:
  // Extends the list of phase changes until it holds one after t.
  void drawChangesUntil(double t) const;
  double uniform() const;  // in [0, 1), 53 random bits

  WindParameters parameters_;
  Vec3 direction_;
  bool blows_ = false;
  // The phase changes drawn so far, in time order, and the phase each one sets. Drawn
  // lazily (pressure() is const): not safe to query from several threads at once.
  mutable std::mt19937_64 random_;
  mutable std::vector<double> changeTimes_;
  mutable std::vector<double> changePhases_;
};

}  // namespace figment
