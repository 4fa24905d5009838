#pragma once
// Named fabric presets (paper §2's material: thickness, density, Young's modulus,
// Poisson's ratio), in SI units, chosen from fabric-level tests rather than fibre data:
//
//   h    thickness at low pressure (KES-F FB3 at 0.5 gf/cm^2, FAST-1 at 2 gf/cm^2), m
//   rho  = W / h, with W the areal density (g/m^2 on the fabric's ticket), kg/m^3
//   E    effective membrane modulus = Eh / h, with Eh the initial tensile stiffness per
//        unit width at drape-level loads (KES-F EMT, FAST-3 E5..E100 region), N/m, Pa
//   nu   in-plane Poisson's ratio: typical figures, fabrics have no single value
//
// The solver bends cloth as a plate, D = E h^3 / (12 (1 - nu^2)), so E is also chosen
// to bring D near the fabric's KES-F bending rigidity B (1 gf.cm^2/cm = 9.807e-5 N.m):
// for thick, loosely bound fabrics (denim, knits) the plate formula with the tensile
// modulus overestimates B, and E sits at the low end of the tensile range.
//
// Explicit time step: an explicit solver is stable for dt <~ C l / c with l the
// shortest section edge and c = sqrt(E / rho) the membrane wave speed. The defaults of
// ClothParameters (E = 1 MPa, rho = 300 kg/m^3: c = 58 m/s; dt = 1.5e-4 s for 1.5 cm
// sections) scale to dt = 1.5e-4 s * (l / 1.5 cm) * (58 m/s / c). Every preset keeps
// c <= kMaxPresetWaveSpeed, so no preset needs a step below ~0.55x the default one.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sim/cloth/Material.h"

namespace figment {

inline constexpr double kMaxPresetWaveSpeed = 105.0;  // m/s

// The preset called `name` (lower case: "cotton", "silk", "denim", "jersey"), or
// nullopt when there is none.
std::optional<Material> materialPreset(std::string_view name);

// Every preset's name, in a fixed order.
std::vector<std::string> materialPresetNames();

// c = sqrt(E / rho), m/s: the speed of membrane waves, which sets the explicit time step.
double membraneWaveSpeed(const Material& material);

}  // namespace figment
