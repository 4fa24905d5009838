#pragma once
// Whether the whole-number fields Coin indexes its own arrays with lie within them. Coin
// grows a per-unit array up to a TextureUnit's unit: `unit -5` corrupted the heap (double
// free), `unit -1` crashed (SIGSEGV), and `unit 2147483647` ran out of memory.

#include <string>

class SoNode;

namespace figment::guard {

// OpenGL names texture units GL_TEXTURE0 to GL_TEXTURE31; Coin warns of and skips a unit past
// what the context has (8 under OSMesa).
inline constexpr int kTextureUnits = 32;

// "" when every such field of every node linked from `root` (NodeLinks.h) lies within its
// range, else one line naming node, field and value: "TextureUnit: unit = -5 is not a texture
// unit: 0 to 31".
std::string firstFieldOutOfRange(const SoNode* root);

}  // namespace figment::guard
