// Coin 4.0 reads the handle of an off-screen context made through our OSMesa callbacks as if
// it were its own GLX context record: cc_glglue_context_max_dimensions() (every
// SoOffscreenRenderer render calls it) tests the record's `pbuffer` flag at byte 64. The
// handle used to be 48 bytes long, so that read went past its end (valgrind memcheck on
// figment-view). The handle now begins with zeros there; this checks it through Coin's own
// C API, the way Coin gets it.
#include <Inventor/C/glue/gl.h>
#include <Inventor/SoDB.h>
#include <gtest/gtest.h>

#include <cstring>

#include "headless/OsmesaForCoin.h"

namespace {

TEST(OsmesaContextHandle, ReadsAsANonPbufferGlxRecordWhereCoinLooks) {
  figment::useOsmesaForCoin();
  SoDB::init();
  void* handle = cc_glglue_context_create_offscreen(32, 32);
  ASSERT_NE(handle, nullptr);
  // Coin's glxglue_contextdata on 64-bit Linux: 9 pointer-sized members, then SbBool pbuffer.
  constexpr size_t kPbufferOffset = 64;
  static_assert(kPbufferOffset + sizeof(int) <= figment::kCoinGlxRecordBytes);
  int pbuffer = -1;
  std::memcpy(&pbuffer, static_cast<const unsigned char*>(handle) + kPbufferOffset, sizeof pbuffer);
  EXPECT_EQ(pbuffer, 0);
  unsigned width = 0, height = 0;
  cc_glglue_context_max_dimensions(&width, &height);  // the call that read past the end
  EXPECT_GT(width, 0u);
  EXPECT_GT(height, 0u);
  cc_glglue_context_destruct(handle);
}

}  // namespace
