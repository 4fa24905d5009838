#include "sim/cloth/Material.h"

#include "sim/core/ParameterChecks.h"

namespace figment {

double Material::bendingStiffness() const {
  return youngsModulus * thickness * thickness * thickness / (12.0 * (1.0 - poissonRatio * poissonRatio));
}

void Material::validate() const {
  requirePositive("thickness", thickness);
  requirePositive("density", density);
  requirePositive("youngsModulus", youngsModulus);
  requireOpenRange("poissonRatio", poissonRatio, -1.0, 0.5);
}

}  // namespace figment
