#pragma once
// Headless start-up: the one call every front end (figment-view, figment-bench, figment-serve's
// workers, the fuzz targets, the tests that render) makes before it reads a scene.

namespace figment {

// Makes Coin render off-screen through OSMesa, with no display: registers FIGMENT's
// OSMesa context callbacks with Coin (useOsmesaForCoin: they must be in place before the first
// SoDB::init()), initialises Coin, installs the one-line Coin message handlers
// (CoinMessages, each line starting with `prefix`) and initialises FIGMENT's node kit. Safe
// to call more than once: the first call decides, and must come before anything else calls
// SoDB::init(). `prefix` must outlive the process's use of Coin (a string literal).
void initHeadless(const char* prefix = "figment-view: warning: ");

}  // namespace figment
