#include "sim/drape/DrapeBody.h"

namespace figment {

int BodyDescription::count(const std::string& what) const {
  for (const auto& [name, n] : counts)
    if (name == what) return n;
  return 0;
}

}  // namespace figment
