#include "io/DrapeRecord.h"

#include <array>
#include <cmath>

#include "io/ByteReader.h"
#include "io/ByteWriter.h"

namespace figment {

namespace {

// A method's enumeration as one byte; `last` its largest value, for the reader's check.
template <class Io, class Enum>
bool enumeration(Io& io, Enum& value, Enum last) {
  std::uint8_t wire = static_cast<std::uint8_t>(value);
  if (!io.template number<std::uint8_t>(wire) || wire > static_cast<std::uint8_t>(last)) return false;
  value = static_cast<Enum>(wire);
  return true;
}

template <class Io, class Report>
bool method(Io& io, Report& r) {
  DrapeMethod& m = r.method;
  bool hasLimit = m.limit.has_value();
  double limit = m.limit.value_or(0.0);
  if (!(enumeration(io, m.integrator, Integrator::Implicit) && enumeration(io, m.contacts, ContactModel::Penalty) &&
        io.template number<double>(m.timeStep) && io.template number<double>(m.maxTimeStep) &&
        enumeration(io, m.limiter, AccelerationLimiter::Tanh) && io.flag(hasLimit) &&
        io.template number<double>(limit)))
    return false;
  m.limit = hasLimit ? std::optional<double>(limit) : std::nullopt;
  return io.template number<double>(r.strainLimit) && io.template number<double>(r.maxTime);
}

template <class Io, class Report>
bool body(Io& io, Report& r) {
  BodyDescription& b = r.body;
  std::uint32_t n = static_cast<std::uint32_t>(b.counts.size());
  if (!io.text(b.kind) || !io.template number<std::uint32_t>(n) || n > 64) return false;
  b.counts.resize(n);
  for (auto& [name, count] : b.counts)
    if (!io.text(name) || !io.template number<std::int32_t>(count)) return false;
  return true;
}

template <class Io, class Report>
bool run(Io& io, Report& r) {
  auto& run = r.run;
  auto& c = run.implicitCosts;
  return io.template number<std::int32_t>(run.iterations) && io.template number<double>(run.simulatedTime) &&
         io.template number<double>(run.wallSeconds) && io.flag(run.atRest) &&
         io.template number<double>(run.clampedSectionShare) && io.template number<double>(run.limitedNodeShare) &&
         io.template number<std::int64_t>(c.steps) && io.template number<std::int64_t>(c.solverIterations) &&
         io.template number<std::int64_t>(c.unconvergedSolves) && io.template number<double>(c.assemblySeconds) &&
         io.template number<double>(c.solveSeconds) && io.template number<double>(c.contactSeconds) &&
         io.template number<std::int64_t>(c.halvedSteps) && io.template number<std::int64_t>(c.failedSteps) &&
         io.template number<double>(run.maxSpeed) && io.template number<double>(run.maxStretch) &&
         io.template number<double>(run.clampedSectionShareAtEnd) &&
         io.template number<double>(run.limitedNodeShareAtEnd);
}

// Every field of DrapeReport in record order, each through `io` (a writer or a reader) as
// a fixed-width type: one list for both directions, so they cannot disagree. Returns
// false when a read ran out of bytes or read a value its field cannot hold.
template <class Io, class Report>
bool eachField(Io& io, Report& r) {
  return method(io, r) && io.text(r.picked) && io.template number<double>(r.pickedDeviation) && io.text(r.pickedBody) &&
         io.text(r.passedOver) && body(io, r) && io.template number<std::int32_t>(r.triangles) && run(io, r) &&
         io.template number<std::int32_t>(r.level) && io.template number<std::int32_t>(r.levels) &&
         io.template number<std::int32_t>(r.sections) && io.template number<double>(r.settling.arrival) &&
         io.template number<double>(r.settling.meanMove) && io.template number<double>(r.settling.maxMove) &&
         io.template number<std::int32_t>(r.startedOverLayers) && io.flag(r.warm) && io.flag(r.fromCache) &&
         io.template number<double>(r.wallSeconds) && io.text(r.garmentWarning) && io.text(r.verdict);
}

struct FieldWriter {
  ByteWriter out;
  template <class Wire, class T>
  bool number(T& value) {
    out.put(static_cast<Wire>(value));
    return true;
  }
  bool flag(bool& value) { return number<std::uint8_t>(value); }
  bool text(std::string& value) {
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

// The drape's shape after its report: positions as float32 triples, sections as int32
// triples, each indexing a position.
void writeShape(ByteWriter& out, const GarmentDrape& drape) {
  std::vector<std::array<float, 3>> points;
  for (const Vec3& x : drape.positions) points.push_back({float(x.x()), float(x.y()), float(x.z())});
  out.putArray(points);
  std::vector<std::array<std::int32_t, 3>> sections;
  for (const Triangle& t : drape.sections) sections.push_back({t[0], t[1], t[2]});
  out.putArray(sections);
}

bool readShape(ByteReader& in, GarmentDrape& drape) {
  std::vector<std::array<float, 3>> points;
  std::vector<std::array<std::int32_t, 3>> sections;
  if (!in.getArray(points) || !in.getArray(sections)) return false;
  for (const auto& p : points) {
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) return false;
    drape.positions.emplace_back(p[0], p[1], p[2]);
  }
  const auto n = static_cast<std::int64_t>(points.size());
  for (const auto& t : sections) {
    for (std::int32_t i : t)
      if (i < 0 || i >= n) return false;
    drape.sections.push_back({t[0], t[1], t[2]});
  }
  return true;
}

}  // namespace

std::vector<unsigned char> writeDrapeRecord(const GarmentDrape& drape) {
  FieldWriter writer;
  writer.out.put(kDrapeRecordVersion);
  DrapeReport copy = drape.report;  // the field list takes its fields by reference, for the reader too
  eachField(writer, copy);
  writeShape(writer.out, drape);
  return writer.out.take();
}

std::optional<GarmentDrape> readDrapeRecord(const std::vector<unsigned char>& record, std::string& problem) {
  problem.clear();
  FieldReader reader{ByteReader(record)};
  std::uint32_t version = 0;
  if (!reader.in.get(version)) {
    problem = "a damaged record";
    return std::nullopt;
  }
  if (version != kDrapeRecordVersion) {
    problem = "a record of version " + std::to_string(version) + ", not " + std::to_string(kDrapeRecordVersion);
    return std::nullopt;
  }
  GarmentDrape drape;
  if (!eachField(reader, drape.report) || !readShape(reader.in, drape) || !reader.in.done()) {
    problem = "a damaged record";
    return std::nullopt;
  }
  return drape;
}

}  // namespace figment
