// The server's cache of workers' answers keeps them by kind and tag within its byte bound,
// the least recently used going first; a fit's advice is never found as an image.

#include <gtest/gtest.h>

#include "serve/http/ImageCache.h"

using namespace figment::serve;

TEST(ImageCache, DropsTheLeastRecentlyUsedPastItsBound) {
  ImageCache cache(10);
  cache.store(JobKind::kRender, "a", std::make_shared<const std::string>("1234"));
  cache.store(JobKind::kRender, "b", std::make_shared<const std::string>("5678"));
  ASSERT_NE(cache.find(JobKind::kRender, "a"), nullptr);  // a is now the more recent
  cache.store(JobKind::kRender, "c", std::make_shared<const std::string>("90ab"));
  EXPECT_NE(cache.find(JobKind::kRender, "a"), nullptr);
  EXPECT_EQ(cache.find(JobKind::kRender, "b"), nullptr);
  EXPECT_EQ(*cache.find(JobKind::kRender, "c"), "90ab");
  EXPECT_LE(cache.bytes(), 10u);
  cache.store(JobKind::kRender, "big", std::make_shared<const std::string>(std::string(11, 'x')));  // never fits
  EXPECT_EQ(cache.find(JobKind::kRender, "big"), nullptr);
}

TEST(ImageCache, AFitsAdviceIsAnEntryOfItsOwnKind) {
  ImageCache cache(100);
  cache.store(JobKind::kFit, "t", std::make_shared<const std::string>("{\"recommended\":\"M\"}"));
  EXPECT_EQ(cache.find(JobKind::kRender, "t"), nullptr);  // not an image, whatever its tag
  ASSERT_NE(cache.find(JobKind::kFit, "t"), nullptr);
  cache.store(JobKind::kRender, "t", std::make_shared<const std::string>("png"));
  EXPECT_EQ(*cache.find(JobKind::kRender, "t"), "png");
  EXPECT_EQ(*cache.find(JobKind::kFit, "t"), "{\"recommended\":\"M\"}");
}
