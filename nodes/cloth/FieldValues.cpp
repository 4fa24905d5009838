#include "nodes/cloth/FieldValues.h"

#include <Inventor/fields/SoFieldContainer.h>
#include <Inventor/fields/SoSFDouble.h>
#include <Inventor/lists/SoFieldList.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace figment {

namespace {

double rounded(double value, int significantDigits) {
  if (!std::isfinite(value)) return value;
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", significantDigits, value);
  return std::strtod(text, nullptr);
}

}  // namespace

double writtenValue(double fieldValue) {
  return rounded(fieldValue, 15);
}

double writtenValue(float fieldValue) {
  return rounded(fieldValue, 7);
}

void snapReadDoubles(SoFieldContainer& container) {
  SoFieldList fields;
  container.getFields(fields);
  for (int i = 0; i < fields.getLength(); ++i) {
    if (!fields[i]->isOfType(SoSFDouble::getClassTypeId())) continue;
    auto* field = static_cast<SoSFDouble*>(fields[i]);
    if (field->isDefault() || field->isConnected()) continue;
    const double snapped = writtenValue(field->getValue());
    if (snapped != field->getValue()) field->setValue(snapped);
  }
}

}  // namespace figment
