#include "headless/OsmesaForCoin.h"

#include <GL/osmesa.h>
#include <Inventor/C/glue/gl.h>

#include <array>
#include <vector>

namespace figment {

namespace {

// One off-screen GL context with the colour buffer it draws into. Coin reads the
// pixels back with glReadPixels, so the buffer is only the context's backing store.
struct OsmesaContext {
  // Coin 4.0's cc_glglue_context_max_dimensions() (called by every SoOffscreenRenderer
  // render) passes the handle our create() returned to glxglue_context_pbuffer_max(), which
  // takes it for its own GLX context record and reads that record's `pbuffer` flag at byte
  // 64: 16 bytes past the end of this struct as it was (valgrind: "Invalid read of size 4").
  // Zeros where Coin looks make the read land inside the handle and say "not a pbuffer",
  // so Coin goes no further with it. Must stay first. (tests/headless/test_OsmesaContextHandle)
  std::array<unsigned char, kCoinGlxRecordBytes> coinGlxRecord{};
  OSMesaContext context = nullptr;
  std::vector<unsigned char> buffer;  // RGBA, 8 bits per channel
  GLsizei width = 0, height = 0;
  // The context that was current before makeCurrent, restored by reinstatePrevious.
  OSMesaContext previous = nullptr;
};

cc_glglue_offscreen_data create(unsigned int width, unsigned int height) {
  // 24-bit depth and 8-bit stencil: the hybrid clothing renderer needs the stencil.
  OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
  if (!context) return nullptr;
  auto* data = new OsmesaContext;
  data->context = context;
  data->width = static_cast<GLsizei>(width);
  data->height = static_cast<GLsizei>(height);
  data->buffer.resize(static_cast<size_t>(width) * height * 4);
  return data;
}

SbBool makeCurrent(cc_glglue_offscreen_data handle) {
  auto* data = static_cast<OsmesaContext*>(handle);
  data->previous = OSMesaGetCurrentContext();
  return OSMesaMakeCurrent(data->context, data->buffer.data(), GL_UNSIGNED_BYTE, data->width, data->height) ? TRUE
                                                                                                            : FALSE;
}

void reinstatePrevious(cc_glglue_offscreen_data handle) {
  auto* data = static_cast<OsmesaContext*>(handle);
  if (!data->previous || data->previous == data->context) return;
  GLint width = 0, height = 0, format = 0;
  void* buffer = nullptr;
  if (OSMesaGetColorBuffer(data->previous, &width, &height, &format, &buffer))
    OSMesaMakeCurrent(data->previous, buffer, GL_UNSIGNED_BYTE, width, height);
  data->previous = nullptr;
}

void destruct(cc_glglue_offscreen_data handle) {
  auto* data = static_cast<OsmesaContext*>(handle);
  if (OSMesaGetCurrentContext() == data->context) OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
  OSMesaDestroyContext(data->context);
  delete data;
}

// Coin keeps the pointer: the table must outlive every render.
cc_glglue_offscreen_cb_functions callbacks = {create, makeCurrent, reinstatePrevious, destruct};

}  // namespace

void useOsmesaForCoin() {
  cc_glglue_context_set_offscreen_cb_functions(&callbacks);
}

}  // namespace figment
