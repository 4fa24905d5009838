#pragma once
// Cloth material in SI units (paper §2: "thickness, density, Young's modulus and
// Poisson's coefficient"). The elastic constants are the fabric's effective membrane
// moduli (fabric tests such as KES), not the fibre's.

#include <string>

namespace figment {

struct Material {
  double thickness = 0.0005;     // h, m
  double density = 300.0;        // rho, kg/m^3 (areal density = rho*h, kg/m^2)
  double youngsModulus = 1.0e6;  // E, Pa
  double poissonRatio = 0.3;     // nu, dimensionless, in (-1, 0.5)

  double arealDensity() const { return density * thickness; }  // kg/m^2
  // Plate bending stiffness D = E h^3 / (12 (1 - nu^2)), N*m.
  double bendingStiffness() const;
  // Throws std::invalid_argument naming the field and value when out of range.
  void validate() const;
};

}  // namespace figment
