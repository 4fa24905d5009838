// The server's image cache keeps images by tag within its byte bound, the least recently
// used going first.

#include <gtest/gtest.h>

#include "serve/http/ImageCache.h"

using namespace figment::serve;

TEST(ImageCache, DropsTheLeastRecentlyUsedPastItsBound) {
  ImageCache cache(10);
  cache.store("a", std::make_shared<const std::string>("1234"));
  cache.store("b", std::make_shared<const std::string>("5678"));
  ASSERT_NE(cache.find("a"), nullptr);  // a is now the more recent
  cache.store("c", std::make_shared<const std::string>("90ab"));
  EXPECT_NE(cache.find("a"), nullptr);
  EXPECT_EQ(cache.find("b"), nullptr);
  EXPECT_EQ(*cache.find("c"), "90ab");
  EXPECT_LE(cache.bytes(), 10u);
  cache.store("big", std::make_shared<const std::string>(std::string(11, 'x')));  // never fits
  EXPECT_EQ(cache.find("big"), nullptr);
}
