#pragma once
// Coin's error and warning messages, turned into what figment-view prints.

#include <string>

namespace figment::viewer {

// Coin reports through handler callbacks, several lines per message. CoinMessages drops
// what is expected noise in a headless program and prints the rest on stderr as one-line
// warnings. While the guard reads a scene its own handlers take Coin's messages
// (guard/ReadMessages.h): read errors become the refusal's one line, and warnings come here
// once the read has succeeded.
class CoinMessages {
 public:
  // Replaces Coin's default handlers; called by initHeadless().
  static void install();
};

}  // namespace figment::viewer
