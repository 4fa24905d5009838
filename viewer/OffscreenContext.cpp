#include "viewer/OffscreenContext.h"

#include <Inventor/SoDB.h>

#include "headless/OsmesaForCoin.h"
#include "nodes/Init.h"
#include "viewer/CoinMessages.h"

namespace figment::viewer {

void initHeadless() {
  static const bool done = [] {
    useOsmesaForCoin();
    SoDB::init();
    CoinMessages::install();  // after SoDB::init(), which installs Coin's default handlers
    figment::init();
    return true;
  }();
  (void)done;
}

}  // namespace figment::viewer
