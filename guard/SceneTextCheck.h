#pragma once
// A look at a scene's text, and at every file it includes, before Coin reads it.
//
// Coin's reader recurses once per level of nesting and once per File include, and has no
// bound on either: a scene that includes itself, or 100,000 nested Separators, overflow
// its stack (SIGSEGV), 10,000 take minutes, and a File naming /dev/zero never ends. The
// text is cheap to scan, so figment-view scans it first and refuses such a scene in one
// line, before Coin is given it. So is a node used inside its own definition (a cycle, and
// a use after free in Coin's reader when the inner node fails to read).

#include <string>

namespace figment::guard {

// Braces and brackets open at once, counted across includes (a File's contents lie one
// level below the File). Shipped scenes nest about 10 deep; Coin reads 1,000 in well
// under a second.
inline constexpr int kMaxNestingDepth = 256;
// Files open at once through File or VRMLInline, one inside another.
inline constexpr int kMaxIncludeDepth = 16;
// Files read through File or VRMLInline in all: a file including the next one twice, 16 deep, would
// otherwise have Coin read 65,536 files.
inline constexpr int kMaxIncludes = 1000;

// Checks the ASCII Inventor (or VRML) text of the scene in `path` and, the way Coin will
// find them, the files its File nodes name, and its VRMLInline (or VRML97 Inline) nodes, whose
// first `url` Coin reads the way it reads a File: each is looked up as SoInput does
// (as given, that is from the working directory; then in the folder of each file being
// read, innermost first; then along SoInput's directories). Returns "" when Coin may read
// it, else one line in ReadMessages' form: "line 3: nesting depth 257 is more than 256",
// "line 2: File { name "a.iv" } includes a file already being read: a.iv -> b.iv ->
// a.iv (in /scenes/b.iv)", "... is not a regular file", "... not found",
// "... would be 17 includes deep, more than 16", "line 9: USE Model inside the
// definition of Model (DEF at line 4): a node cannot hold itself".
//
// What is not ASCII text cannot be checked, and is refused, the scene or an include: gzip or
// bzip2 (Coin decompresses them), binary Inventor, a 3D Studio file (headerless, beginning
// "MM": Coin's reader can loop forever), anything else without a header: "a gzip-compressed
// file: decompress it first", "line 3: File { name "g.iv" } names a binary Inventor file: ...".
std::string checkSceneText(const std::string& path);

}  // namespace figment::guard
