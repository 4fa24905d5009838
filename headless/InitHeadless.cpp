#include "headless/InitHeadless.h"

#include <Inventor/SoDB.h>

#include "headless/CoinMessages.h"
#include "headless/OsmesaForCoin.h"
#include "nodes/Init.h"

namespace figment {

void initHeadless(const char* prefix) {
  static const bool done = [prefix] {
    useOsmesaForCoin();
    SoDB::init();
    CoinMessages::install(prefix);  // after SoDB::init(), which installs Coin's default handlers
    figment::init();
    return true;
  }();
  (void)done;
}

}  // namespace figment
