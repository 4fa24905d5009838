#pragma once
// Headless rendering: Coin draws into an OSMesa context instead of a window system's.

namespace figment {

// Registers OSMesa context callbacks with Coin, so SoOffscreenRenderer renders with no
// display (24-bit depth, 8-bit stencil: the hybrid clothing renderer needs the stencil).
// Must come before the first SoDB::init(); safe to call more than once. A program using
// it links figment_headless, which also compiles GlxForwarding.cpp into it (without
// that, Coin's vertex-array drawing is silently blank).
void useOsmesaForCoin();

// The handle of a context made through these callbacks begins with this many zero bytes:
// Coin reads some of them as if the handle were its own GLX context record (its
// glxglue_contextdata: 72 bytes on 64-bit Linux; see OsmesaForCoin.cpp).
inline constexpr unsigned kCoinGlxRecordBytes = 96;

}  // namespace figment
