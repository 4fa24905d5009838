#pragma once
// Coin's error and warning messages, turned into what a program (figment-view,
// figment-bench) prints.

#include <string>

namespace figment::viewer {

// Coin reports through handler callbacks, several lines per message. CoinMessages drops
// what is expected noise in a headless program and prints the rest on stderr as one-line
// warnings. While the guard reads a scene its own handlers take Coin's messages
// (guard/ReadMessages.h): read errors become the refusal's one line, and warnings come here
// once the read has succeeded.
class CoinMessages {
 public:
  // Replaces Coin's default handlers with ones that print "<program>: warning: ...";
  // called by initHeadless() for figment-view. Once installed, a later call keeps the
  // first program's name (figment-bench installs its own, then may render headless).
  // `program` must outlive the process's use of Coin (a string literal).
  static void install(const char* program = "figment-view");
};

}  // namespace figment::viewer
