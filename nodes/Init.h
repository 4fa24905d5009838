#pragma once
// The one entry point that makes FIGMENT's node kit known to Coin.

namespace figment {

// Registers every FIGMENT node and engine class (nodes/NodeTypes.h: the one list)
// with Coin's type system, so .iv files naming them can be read. Calls SoDB::init()
// first when nobody has yet. Safe to call more than once.
//
// A program that renders off-screen must register its GL context callbacks before
// the first SoDB::init() (headless/InitHeadless.h does it all), that is before this call.
void init();

}  // namespace figment
