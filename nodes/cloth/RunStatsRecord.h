#pragma once
// A drape's statistics (ClothEngine::RunStats) as the drape cache keeps them beside the
// positions: a version, then each field in turn with a fixed width (int32, int64,
// float64, a byte for a bool, a length and the characters for a text), so a record
// never depends on how the compiler lays out the struct. A record of another version,
// or one that is too short or too long for this version, is not read: the engine drops
// the entry and drapes again.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "nodes/cloth/ClothEngine.h"

namespace figment {

// Raised whenever a field is added, removed or changes its type or order. 1 was the
// struct's bytes as they lay in memory, before records had a version.
constexpr std::uint32_t kRunStatsRecordVersion = 4;

std::vector<unsigned char> writeRunStats(const ClothEngine::RunStats& stats);

// The statistics in `record`, or nullopt with `problem` saying why not ("a record of
// version 7, not 2", "a damaged record").
std::optional<ClothEngine::RunStats> readRunStats(const std::vector<unsigned char>& record, std::string& problem);

}  // namespace figment
