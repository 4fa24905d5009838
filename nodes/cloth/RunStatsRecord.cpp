#include "nodes/cloth/RunStatsRecord.h"

#include "io/ByteReader.h"
#include "io/ByteWriter.h"

namespace figment {

namespace {

// Every field of RunStats in record order, each through `io` (a writer or a reader) as
// a fixed-width type: one list for both directions, so they cannot disagree. Returns
// false when a read ran out of bytes.
template <class Io, class Stats>
bool eachField(Io& io, Stats& s) {
  return io.template number<std::int32_t>(s.triangles) && io.template number<std::int32_t>(s.iterations) &&
         io.template number<double>(s.simulatedSeconds) && io.template number<double>(s.wallSeconds) &&
         io.flag(s.atRest) && io.template number<double>(s.clampedSectionShare) &&
         io.template number<double>(s.limitedNodeShare) && io.template number<std::int64_t>(s.implicitSteps) &&
         io.template number<std::int64_t>(s.solverIterations) && io.template number<double>(s.assemblySeconds) &&
         io.template number<double>(s.solveSeconds) && io.template number<double>(s.contactSeconds) &&
         io.template number<std::int32_t>(s.level) && io.template number<std::int32_t>(s.levels) &&
         io.template number<std::int32_t>(s.sections) && io.template number<double>(s.endLevelSeconds) &&
         io.template number<double>(s.meanMoveAfterEndLevel) && io.template number<double>(s.maxMoveAfterEndLevel) &&
         io.flag(s.fromCache) && io.text(s.picked) && io.template number<double>(s.pickedDeviation) &&
         io.text(s.pickedBody) && io.text(s.passedOver) && io.text(s.integrator) && io.text(s.contactModel) &&
         io.text(s.accelerationLimiter) && io.template number<double>(s.timeStep) &&
         io.template number<double>(s.strainLimit) && io.template number<double>(s.accelerationLimit) &&
         io.template number<double>(s.maxTime) && io.template number<double>(s.maxSpeed) &&
         io.template number<double>(s.maxStretch) && io.template number<double>(s.clampedSectionShareAtEnd) &&
         io.template number<double>(s.limitedNodeShareAtEnd) && io.template number<std::int64_t>(s.halvedSteps) &&
         io.template number<std::int64_t>(s.failedSteps) && io.text(s.garmentWarning);
}

struct FieldWriter {
  ByteWriter out;
  template <class Wire, class T>
  bool number(const T& value) {
    out.put(static_cast<Wire>(value));
    return true;
  }
  bool flag(bool value) { return number<std::uint8_t>(value ? 1 : 0); }
  bool text(const std::string& value) {
    out.putText(value);
    return true;
  }
};

struct FieldReader {
  ByteReader in;
  template <class Wire, class T>
  bool number(T& value) {
    Wire wire{};
    if (!in.get(wire)) return false;
    value = static_cast<T>(wire);
    return true;
  }
  bool flag(bool& value) {
    std::uint8_t wire = 0;
    if (!in.get(wire) || wire > 1) return false;
    value = wire == 1;
    return true;
  }
  bool text(std::string& value) { return in.getText(value); }
};

}  // namespace

std::vector<unsigned char> writeRunStats(const ClothEngine::RunStats& stats) {
  FieldWriter writer;
  writer.out.put(kRunStatsRecordVersion);
  eachField(writer, stats);
  return writer.out.take();
}

std::optional<ClothEngine::RunStats> readRunStats(const std::vector<unsigned char>& record, std::string& problem) {
  problem.clear();
  FieldReader reader{ByteReader(record)};
  std::uint32_t version = 0;
  if (!reader.in.get(version)) {
    problem = "a damaged record";
    return std::nullopt;
  }
  if (version != kRunStatsRecordVersion) {
    problem = "a record of version " + std::to_string(version) + ", not " + std::to_string(kRunStatsRecordVersion);
    return std::nullopt;
  }
  ClothEngine::RunStats stats;
  if (!eachField(reader, stats) || !reader.in.done()) {
    problem = "a damaged record";
    return std::nullopt;
  }
  return stats;
}

}  // namespace figment
