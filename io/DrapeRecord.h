#pragma once
// A finished drape (sim/drape/GarmentDrape.h) as the drape cache keeps it (io/DrapeCache.h):
// a version, then each field of its report in turn with a fixed width (int32, int64,
// float64, a byte for a bool or a method's enumeration, a length and the characters for a
// text), so a record never depends on how the compiler lays out the struct; then its
// positions as the engine draws them (float32 x, y, z each) and its sections (int32
// triples). A record of another version, or one that is too short or too long for this
// version, or with a value no field can hold, is not read: the engine drops the entry and
// drapes again. A sewn drape's sewing is not kept (its report says how it ended).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sim/drape/GarmentDrape.h"

namespace figment {

// Raised whenever a field is added, removed or changes its type or order. 1 was the
// struct's bytes as they lay in memory, before records had a version; 4 the last
// figment::DrapeReport; 5 the first DrapeReport (its method as enumerations, its body);
// 6 the whole drape in one record (the positions and sections after the report); 7 the
// nodes started over the layers beneath (DrapeReport::startedOverLayers); 8 a growing
// implicit step's largest (DrapeMethod::maxTimeStep).
constexpr std::uint32_t kDrapeRecordVersion = 8;

std::vector<unsigned char> writeDrapeRecord(const GarmentDrape& drape);

// The drape in `record`, or nullopt with `problem` saying why not ("a record of
// version 7, not 6", "a damaged record").
std::optional<GarmentDrape> readDrapeRecord(const std::vector<unsigned char>& record, std::string& problem);

}  // namespace figment
