#pragma once
// Reading an .iv scene file through the guard: the text checked before Coin reads it, Coin's
// reader watched as it reads, the graph checked before any action traverses it. Part of the
// guard's public entry (guard/Guard.h).

#include <string>

class SoSeparator;

namespace figment::guard {

// Reads the scene in `path`. Returns its root, referenced once (the caller unrefs it), or null
// with `error` set to one line naming what went wrong, e.g. "no such file", "line 12: Node type
// ``Foo'' not recognized.", "line 3: MeshFile 'Body': fileName ..."; from the check of its text
// before Coin reads it (SceneTextCheck.h), "line 9: nesting depth 257 is more than 256"; from
// the watch on Coin's reader (GuardedInput.h), "line 4: CapsuleVolume: fields [ SFFloat r1e308 ]
// declares a field CapsuleVolume does not have (in volumes.iv)"; from the check of the graph
// read (SceneExpansion.h, NodeFieldTypes.h, NodeFieldRanges.h), "the scene would draw more than
// 20000 nodes, ...".
//
// Coin must be initialised (SoDB::init(); FIGMENT's nodes registered by figment::init(), or
// loaded by name through Coin's dynamic loading). Coin's messages during the read are the
// guard's (ReadMessages.h): its warnings reach the program's handler when the read succeeds.
SoSeparator* readScene(const std::string& path, std::string& error);

}  // namespace figment::guard
