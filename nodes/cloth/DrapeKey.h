#pragma once
// The text a ClothEngine's drape is cached under (io/DrapeCache.h): everything that
// shapes the drape. Every input field of the engine; the body it collides with, as
// every field of every node under it (through node fields, children and File nodes)
// and each MeshFile's collision surface; the progressive script's file; with a
// tolerance, the tradeoff table it picks from; and the node library's own build (the
// file that holds this code, found by dladdr: its path, size and time), so a rebuilt
// library never reads a drape an older one made, whichever program loads it (python3
// under pivy too). Numbers enter as their bits, not as text; large
// arrays as their size and two 64-bit digests.

#include <string>

class ClothEngine;

namespace figment {

// `scriptPath`: the engine's progressiveScript as resolved ("" for none).
std::string drapeKey(const ClothEngine& engine, const std::string& scriptPath);

}  // namespace figment
