#pragma once
// FIGMENT's node and engine classes, listed once. figment::init() registers them with Coin
// from this list, nodes/CMakeLists.txt makes each one's lib<Class>.so link (Coin's dynamic
// loading) from the names in NodeTypes.cpp, and tests/nodes/test_NodeTypes.cpp holds the list
// equal to the classes nodes/ declares, to what Coin learns from figment::init() and to the
// examples in scenes/examples/.

#include <span>

namespace figment {

struct NodeType {
  const char* name;     // the class's name: its keyword in .iv files
  void (*initClass)();  // registers it (and an abstract base it has) with Coin
};

// Every concrete node and engine class of the kit, in the order figment::init() registers them.
std::span<const NodeType> nodeTypes();

}  // namespace figment
