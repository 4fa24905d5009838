#pragma once
// Headless rendering: Coin draws into an OSMesa context instead of a window system's.

namespace figment::viewer {

// Makes Coin render off-screen through OSMesa, with no display: registers FIGMENT's
// OSMesa context callbacks with Coin (they must be in place before the first
// SoDB::init()), initialises Coin, installs the Coin message handlers (CoinMessages)
// and initialises FIGMENT's node kit. Safe to call more than once; the first call must come
// before anything else calls SoDB::init().
void initHeadless();

}  // namespace figment::viewer
