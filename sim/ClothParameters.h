#pragma once
// Everything that shapes one drape besides the garment and the body (SI units).

#include "Material.h"
#include "TriangleMesh.h"

namespace figment {

struct RestRule {
  double speedThreshold = 0.01;  // m/s: the cloth is at rest when every node is slower...
  double window = 0.25;          // s: ...for this long without interruption
};

struct ClothParameters {
  Material material;
  double timeStep = 1.5e-4;              // dt, s: stable for ~1.5 cm sections of 1 MPa cloth
  double maxTime = 5.0;                  // s of simulated time, the run's upper bound
  RestRule rest;
  Vec3 gravity = Vec3(0.0, -9.81, 0.0);  // m/s^2
  double airResistance = 1.0;            // N*s/m^3: force per unit area per unit speed
  double friction = 0.4;                 // Coulomb coefficient against the body
  double clearance = 0.003;              // m kept between cloth nodes and the body surface
  double strainRateDamping = 1.0e-4;     // s: Kelvin-Voigt relaxation time of the membrane

  // Throws std::invalid_argument naming the field and value when out of range.
  void validate() const;
};

}  // namespace figment
