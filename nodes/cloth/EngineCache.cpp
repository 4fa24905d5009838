#include "nodes/cloth/EngineCache.h"

#include <chrono>

#include "io/DrapeCache.h"
#include "io/DrapeReportRecord.h"

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
  const std::optional<CachedDrape> cached = cache_->find(key, message);
  if (!cached || static_cast<int>(cached->positions.size()) != numRest) return std::nullopt;
  std::string problem;
  std::optional<DrapeReport> report = readDrapeReport(cached->stats, problem);
  if (!report) {
    cache_->remove(key);
    message = cache_->entryPath(key).string() + ": " + problem + ", removed; draped again";
    return std::nullopt;
  }
  out.positions.clear();
  for (const auto& p : cached->positions) out.positions.emplace_back(p[0], p[1], p[2]);
  out.indices = cached->sectionIndices;
  report->fromCache = true;
  report->wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

void EngineCache::keep(const std::string& key, const EngineOutput& out, const DrapeReport& report,
                       std::string& message) const {
  if (!cache_ || key.empty()) return;
  CachedDrape drape;
  for (const SbVec3f& p : out.positions) drape.positions.push_back({p[0], p[1], p[2]});
  drape.sectionIndices = out.indices;
  drape.stats = writeDrapeReport(report);
  const std::string problem = cache_->store(key, drape);
  if (!problem.empty()) message = "drape cache: " + problem;
}

}  // namespace figment
