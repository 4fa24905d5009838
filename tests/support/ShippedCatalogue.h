#pragma once
// The garment catalogue shipped with the sources (scenes/catalogue/index.txt), read once:
// what the service checks a made body's requests against.

#include "io/GarmentCatalogue.h"

namespace figment::test {

inline const GarmentCatalogue& shippedCatalogue() {
  static const GarmentCatalogue catalogue(defaultCataloguePath());
  return catalogue;
}

}  // namespace figment::test
