#include "sim/cloth/MaterialPresets.h"

// Based on:
// - S. Kawabata, "The Standardization and Analysis of Hand Evaluation", 2nd ed., The
//   Textile Machinery Society of Japan, 1980: KES-F thickness T (FB3), tensile EMT/LT
//   (FB1) and bending rigidity B (FB2) of apparel fabrics.
// - J. Hu, "Fabric Testing", Woodhead Publishing, 2008: ranges of KES-F and FAST values
//   for shirting, suiting, denim and knits.
// - A. De Boos, D. Tester, "SiroFAST: Fabric Assurance by Simple Testing", CSIRO, 1994,
//   and P. G. Minazio, "FAST - Fabric Assurance by Simple Testing", Int. J. Clothing
//   Sci. Tech. 7(2/3), 1995: extensibility E5/E20/E100 at 5/20/100 gf/cm.
// - P. Volino, N. Magnenat-Thalmann, F. Faure, "A simple approach to nonlinear tensile
//   stiffness for accurate cloth simulation", ACM TOG 28(4), 2009: tensile stiffnesses
//   of real fabrics measured with KES, in N/m, used as cloth-simulation moduli.
// The figures below are typical values for each fabric class from these sources, not
// measurements of one fabric; each comment says how the value was reached.

#include <array>
#include <cmath>

namespace figment {

namespace {

struct Preset {
  const char* name;
  Material material;
};

Material make(double thickness, double arealDensity, double youngsModulus, double poissonRatio) {
  Material m;
  m.thickness = thickness;
  m.density = arealDensity / thickness;
  m.youngsModulus = youngsModulus;
  m.poissonRatio = poissonRatio;
  return m;
}

const std::array<Preset, 4>& presets() {
  static const std::array<Preset, 4> table = {{
      // Cotton shirting (plain-woven poplin/broadcloth). W = 120 g/m^2 (shirting is
      // 110-150 g/m^2, Hu 2008); KES-F T = 0.30 mm (0.25-0.35 mm). FAST E100 of shirting
      // is ~1.5-3 %, a secant stiffness of 3-6 kN/m at 98 N/m; at drape loads (< 5 N/m,
      // the E5..E20 crimp region) it is softer: Eh = 1.2 kN/m, E = 1.2e3 / 3e-4 = 4 MPa.
      // Then D = 9.6e-6 N.m = 0.098 gf.cm^2/cm, within KES B of shirting (0.05-0.15).
      // nu = 0.25: a typical simulation figure for wovens (Volino et al. 2009 range).
      {"cotton", make(0.30e-3, 0.120, 4.0e6, 0.25)},
      // Silk (crepe de chine / habotai). W = 70 g/m^2 (silk dress fabrics 60-90 g/m^2);
      // KES-F T = 0.20 mm. Fine filament yarns with little crimp but low yarn count:
      // Eh = 0.5 kN/m at drape loads, E = 0.5e3 / 2e-4 = 2.5 MPa. D = 1.8e-6 N.m =
      // 0.018 gf.cm^2/cm, within KES B of silks (0.01-0.03). nu = 0.25 (typical figure).
      {"silk", make(0.20e-3, 0.070, 2.5e6, 0.25)},
      // Denim (3/1 twill, ~12 oz/yd^2). W = 400 g/m^2 (350-450 g/m^2); KES-F T =
      // 0.80 mm (0.7-1.0 mm). Its tensile stiffness (FAST E100 ~1-2 %: 5-10 kN/m secant)
      // with the plate formula would give D far above KES B; E = 3 MPa (Eh = 2.4 kN/m,
      // the low end) gives D = 1.4e-4 N.m = 1.4 gf.cm^2/cm, the stiff end of denim's B
      // (0.3-1.5 gf.cm^2/cm). nu = 0.25 (typical figure).
      {"denim", make(0.80e-3, 0.400, 3.0e6, 0.25)},
      // Cotton single jersey (weft knit, T-shirts). W = 170 g/m^2 (150-200 g/m^2);
      // KES-F T = 0.60 mm (0.5-0.7 mm). Knits extend by loop deformation: initial
      // tensile stiffness ~0.1-0.3 kN/m (FAST E100 of knits is 10-40 %); Eh = 0.18 kN/m,
      // E = 0.18e3 / 6e-4 = 0.3 MPa. D = 6.2e-6 N.m = 0.063 gf.cm^2/cm (KES B of
      // jerseys 0.02-0.08). nu = 0.35: knits contract more than wovens (typical figure).
      {"jersey", make(0.60e-3, 0.170, 0.3e6, 0.35)},
  }};
  return table;
}

}  // namespace

std::optional<Material> materialPreset(std::string_view name) {
  for (const Preset& preset : presets())
    if (name == preset.name) return preset.material;
  return std::nullopt;
}

std::vector<std::string> materialPresetNames() {
  std::vector<std::string> names;
  for (const Preset& preset : presets()) names.emplace_back(preset.name);
  return names;
}

double membraneWaveSpeed(const Material& material) {
  return std::sqrt(material.youngsModulus / material.density);
}

}  // namespace figment
