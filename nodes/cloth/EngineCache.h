#pragma once
// Internal to figment_nodes (not installed): a ClothEngine's output, from a drape or from
// the drape cache (io/DrapeCache.h): read from an entry, or kept in one, as the drape's
// record (io/DrapeRecord.h: its report, positions and sections).

#include <Inventor/SbVec3f.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sim/drape/DrapeReport.h"
#include "sim/drape/GarmentDrape.h"

namespace figment {

class DrapeCache;

// What an engine outputs: its positions and levelCoordIndex.
struct EngineOutput {
  std::vector<SbVec3f> positions;
  std::vector<std::int32_t> indices;

  // `drape`'s positions (as floats, one per rest point) and its sections as coordIndex,
  // each ended by -1.
  void take(const GarmentDrape& drape);
};

class EngineCache {
 public:
  explicit EngineCache(const DrapeCache* cache) : cache_(cache) {}  // null: no cache
  explicit operator bool() const { return cache_ != nullptr; }

  // The drape kept under `key`, when there is one for `numRest` rest points: `out` set
  // from it and its report returned, fromCache and with wallSeconds the time to find and
  // read it. An entry whose record this build cannot read (another version, damaged) is
  // removed and `message` says so; nullopt then, and when there is none.
  std::optional<DrapeReport> read(const std::string& key, int numRest, EngineOutput& out, std::string& message) const;
  // Keeps `drape` under `key`; `message` says what went wrong, if anything.
  void keep(const std::string& key, const GarmentDrape& drape, std::string& message) const;

 private:
  const DrapeCache* cache_;
};

}  // namespace figment
