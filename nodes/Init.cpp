#include "nodes/Init.h"

#include <Inventor/SoDB.h>

#include "nodes/NodeTypes.h"

namespace figment {

void init() {
  SoDB::init();  // a no-op when Coin is already initialised
  // Each initClass() returns at once when its class is already registered, so a
  // second init(), or a class Coin loaded on its own through libX.so, is harmless.
  for (const NodeType& type : nodeTypes()) type.initClass();
}

}  // namespace figment
