#pragma once
// The one line a check refuses with: the text of the std::invalid_argument it throws, or ""
// when it accepts. Tests compare it whole, so a refusal that stops naming its field fails.

#include <stdexcept>
#include <string>

namespace figment::test {

template <class Check>
std::string refusal(Check&& check) {
  try {
    check();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace figment::test
