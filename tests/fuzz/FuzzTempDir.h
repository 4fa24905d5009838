#pragma once
// A private working folder for a fuzz target: made once, the process moves into it, and
// each input is written there as a file, since FIGMENT's readers take paths (Coin's SoInput
// for includes, assimp for meshes). Relative names in an input then resolve inside it.

#include <cstddef>
#include <cstdint>
#include <string>

namespace figment::fuzz {

// Makes a fresh folder under $TMPDIR (or /tmp) and changes the working directory to it.
// Returns its path. Aborts when it cannot: a fuzz run without it would be meaningless.
std::string enterTempDir(const char* prefix);

// Writes `size` bytes to `name` in the working directory (replacing it). Aborts on failure.
void writeFile(const std::string& name, const uint8_t* data, size_t size);
void writeFile(const std::string& name, const std::string& text);

}  // namespace figment::fuzz
