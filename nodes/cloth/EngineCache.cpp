#include "nodes/cloth/EngineCache.h"

#include <chrono>

#include "io/DrapeCache.h"
#include "io/DrapeRecord.h"

namespace figment {

void EngineOutput::take(const GarmentDrape& drape) {
  for (size_t i = 0; i < drape.positions.size() && i < positions.size(); ++i) {
    const Vec3& x = drape.positions[i];
    positions[i].setValue(float(x.x()), float(x.y()), float(x.z()));
  }
  indices.clear();
  for (const Triangle& t : drape.sections) indices.insert(indices.end(), {t[0], t[1], t[2], -1});
}

std::optional<DrapeReport> EngineCache::read(const std::string& key, int numRest, EngineOutput& out,
                                             std::string& message) const {
  if (!cache_ || key.empty()) return std::nullopt;
  const auto start = std::chrono::steady_clock::now();
  const std::optional<std::vector<unsigned char>> record = cache_->find(key, message);
  if (!record) return std::nullopt;
  std::string problem;
  std::optional<GarmentDrape> drape = readDrapeRecord(*record, problem);
  if (!drape) {
    cache_->remove(key);
    message = cache_->entryPath(key).string() + ": " + problem + ", removed; draped again";
    return std::nullopt;
  }
  if (static_cast<int>(drape->positions.size()) != numRest) return std::nullopt;
  out.take(*drape);
  DrapeReport& report = drape->report;
  report.fromCache = true;
  report.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return std::move(report);
}

void EngineCache::keep(const std::string& key, const GarmentDrape& drape, std::string& message) const {
  if (!cache_ || key.empty()) return;
  const std::string problem = cache_->store(key, writeDrapeRecord(drape));
  if (!problem.empty()) message = "drape cache: " + problem;
}

}  // namespace figment
