#pragma once
// Reading an .iv scene file, with Coin's read errors turned into one line.

#include <string>

class SoSeparator;

namespace figment::viewer {

// Reads the scene in `path`. Returns its root, referenced once (the caller unrefs it),
// or null with `error` set to one line naming what went wrong, e.g. "cannot open file",
// "line 12: Unknown class \"Foo\"", "line 3: MeshFile 'Body': fileName ..." or, from the
// check of its text before Coin reads it (SceneTextCheck.h), "line 9: nesting depth 257
// is more than 256", or from the check of the graph read (SceneExpansion.h), "the scene
// would draw more than 20000 nodes, ...".
// Needs initHeadless() (for the read-error capture) first.
SoSeparator* readSceneFile(const std::string& path, std::string& error);

}  // namespace figment::viewer
