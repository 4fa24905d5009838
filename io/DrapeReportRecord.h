#pragma once
// A drape's report (sim/drape/DrapeReport.h) as the drape cache keeps it beside the
// positions (io/DrapeCache.h): a version, then each field in turn with a fixed width
// (int32, int64, float64, a byte for a bool or a method's enumeration, a length and the
// characters for a text), so a record never depends on how the compiler lays out the
// struct. A record of another version, or one that is too short or too long for this
// version, or with a value no field can hold, is not read: the engine drops the entry and
// drapes again.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sim/drape/DrapeReport.h"

namespace figment {

// Raised whenever a field is added, removed or changes its type or order. 1 was the
// struct's bytes as they lay in memory, before records had a version; 4 the last
// figment::DrapeReport; 5 the first DrapeReport (its method as enumerations, its body).
constexpr std::uint32_t kDrapeReportRecordVersion = 5;

std::vector<unsigned char> writeDrapeReport(const DrapeReport& report);

// The report in `record`, or nullopt with `problem` saying why not ("a record of
// version 7, not 5", "a damaged record").
std::optional<DrapeReport> readDrapeReport(const std::vector<unsigned char>& record, std::string& problem);

}  // namespace figment
