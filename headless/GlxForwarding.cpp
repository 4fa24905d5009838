// glXGetProcAddress / glXGetProcAddressARB, forwarded to OSMesa.
//
// Why: Debian's libCoin links the GLVND libraries and fetches OpenGL extension entry
// points (vertex arrays, VBOs) through glXGetProcAddress. With an OSMesa context
// current, GLVND's glX hands back dispatch entries that never reach OSMesa, and shapes
// drawn through vertex arrays (large face sets, BASE_COLOR lighting) come out blank
// without any error. Defining these two functions in the executable, exported with
// -rdynamic, makes Coin's look-up find OSMesa's real functions instead.
//
// This file is compiled into every executable that renders (figment-view, the viewer
// tests, the plain-Coin rendering test) through figment_headless's INTERFACE sources:
// an archive member nobody calls would otherwise be left out by the linker, silently
// bringing the bug back.

#include <GL/osmesa.h>

namespace {

using ProcAddress = void (*)();

ProcAddress forward(const unsigned char* name) {
  return reinterpret_cast<ProcAddress>(OSMesaGetProcAddress(reinterpret_cast<const char*>(name)));
}

}  // namespace

extern "C" {

__attribute__((visibility("default"))) ProcAddress glXGetProcAddress(const unsigned char* name) {
  return forward(name);
}

__attribute__((visibility("default"))) ProcAddress glXGetProcAddressARB(const unsigned char* name) {
  return forward(name);
}

}  // extern "C"
