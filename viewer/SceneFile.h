#pragma once
// Reading an .iv scene file, with Coin's read errors turned into one line.

#include <string>

class SoSeparator;

namespace figment::viewer {

// Reads the scene in `path`. Returns its root, referenced once (the caller unrefs it),
// or null with `error` set to one line naming what went wrong, e.g. "cannot open file",
// "line 12: Unknown class \"Foo\"" or "line 3: MeshFile 'Body': fileName ...".
// Needs initHeadless() (for the read-error capture) first.
SoSeparator* readSceneFile(const std::string& path, std::string& error);

}  // namespace figment::viewer
