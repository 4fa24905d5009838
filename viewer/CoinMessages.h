#pragma once
// Coin's error and warning messages, turned into what figment-view prints.

#include <string>
#include <vector>

namespace figment::viewer {

// Coin reports through handler callbacks, several lines per message. CoinMessages keeps
// read errors as one line each for the caller to report, drops what is expected noise
// in a headless program, and prints the rest on stderr as one-line warnings.
class CoinMessages {
 public:
  // Replaces Coin's default handlers; called by initHeadless().
  static void install();
  // Read errors since the last call, oldest first, each one line:
  // "line 4: MeshFile 'Body': fileName "nothere.obj" not found" (with "in FILE"
  // appended when the error lies in another file than `scene`).
  static std::vector<std::string> takeReadErrors(const std::string& scene);
  // While a scene is read: warnings wait, and are printed by releaseWarnings(true) when
  // the read succeeds, or dropped by releaseWarnings(false) when it fails (its one-line
  // error names the cause; Coin's warnings on the way there would make it several).
  static void holdWarnings();
  static void releaseWarnings(bool print);
  // Coin's multi-line message as one line: "Coin read error: " dropped, lines joined.
  static std::string oneLine(const std::string& message);
};

}  // namespace figment::viewer
