#pragma once
// Coin's error and warning messages, turned into what a front end (figment-view,
// figment-bench, figment-serve's workers) prints.

namespace figment {

// Coin reports through handler callbacks, several lines per message. CoinMessages drops
// what is expected noise in a headless program and prints the rest on stderr, one line
// each. While the guard reads a scene its own handlers take Coin's messages
// (guard/ReadMessages.h): read errors become the refusal's one line, and warnings come here
// once the read has succeeded.
class CoinMessages {
 public:
  // Replaces Coin's default handlers with ones that print `prefix` and the message in one
  // line ("figment-view: warning: ..."); called by initHeadless(). Once installed, a later
  // call keeps the first prefix. `prefix` must outlive the process's use of Coin (a string
  // literal).
  static void install(const char* prefix);
};

}  // namespace figment
