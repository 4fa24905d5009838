#include "headless/CoinMessages.h"

#include <Inventor/errors/SoDebugError.h>
#include <Inventor/errors/SoReadError.h>

#include <iostream>
#include <string>

#include "guard/ReadMessages.h"

namespace figment {

namespace {

void onDebugMessage(const SoError* error, void* prefix) {
  const std::string text = error->getDebugString().getString();
  // Coin asks GLX whether rendering is direct even when no GLX context exists.
  if (text.find("glxglue_isdirect") != std::string::npos) return;
  // A ClothEngine's error is its lastError(), which the program reports itself.
  if (text.find("ClothEngine::evaluate") != std::string::npos) return;
  std::cerr << static_cast<const char*>(prefix) << guard::ReadMessages::oneLine(text) << "\n";
}

// A read error outside the guard's reads (the guard takes those of a scene's read): none is
// known; one would be a warning, in one line.
void onReadError(const SoError* error, void* data) {
  onDebugMessage(error, data);
}

}  // namespace

void CoinMessages::install(const char* prefix) {
  if (SoDebugError::getHandlerCallback() == onDebugMessage) return;
  void* name = const_cast<char*>(prefix);  // Coin passes it back as the callbacks' data
  SoReadError::setHandlerCallback(onReadError, name);
  SoDebugError::setHandlerCallback(onDebugMessage, name);
}

}  // namespace figment
