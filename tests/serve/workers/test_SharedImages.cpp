// Images in a shared store: what is stored under a tag comes back byte for byte under it;
// an entry damaged anywhere, cut short, or stored under another tag (foreign) is dropped
// from the store, never answered.

#include <gtest/gtest.h>

#include <map>

#include "serve/workers/SharedImages.h"
#include "support/MemoryStore.h"

using namespace figment::serve;

using figment::test::MemoryStore;

namespace {

const std::string kTag = "0123456789abcdef0123456789abcdef";
const std::string kOtherTag = "fedcba9876543210fedcba9876543210";

std::string someImage() {
  std::string image = "\x89PNG\r\n\x1a\n";
  for (int i = 0; i < 300; ++i) image += char(i * 7);
  return image;
}

}  // namespace

TEST(SharedImages, GivesBackWhatWasStoredUnderItsTagOnly) {
  const auto store = std::make_shared<MemoryStore>();
  const SharedImages images(store);
  ASSERT_TRUE(images.store(JobKind::kRender, kTag, someImage()));
  ASSERT_EQ(store->entries.count(SharedImages::nameOf(JobKind::kRender, kTag)), 1u);
  const std::shared_ptr<const std::string> back = images.find(JobKind::kRender, kTag);
  ASSERT_NE(back, nullptr);
  EXPECT_EQ(*back, someImage());
  EXPECT_EQ(images.find(JobKind::kRender, kOtherTag), nullptr);
  EXPECT_EQ(store->entries.size(), 1u);  // a miss drops nothing
}

TEST(SharedImages, ADamagedEntryIsDroppedNeverAnswered) {
  const std::string entry = SharedImages::encode(kTag, someImage());
  for (size_t at = 0; at < entry.size(); at += 13) {
    std::string damaged = entry;
    damaged[at] ^= 0x10;
    EXPECT_EQ(SharedImages::decode(kTag, damaged), nullptr) << "byte " << at;
  }
  EXPECT_EQ(SharedImages::decode(kTag, entry.substr(0, entry.size() - 1)), nullptr);
  EXPECT_EQ(SharedImages::decode(kTag, entry + "x"), nullptr);
  EXPECT_EQ(SharedImages::decode(kTag, ""), nullptr);
  ASSERT_NE(SharedImages::decode(kTag, entry), nullptr);  // the control: undamaged, it reads

  const auto store = std::make_shared<MemoryStore>();
  const SharedImages images(store);
  store->entries[SharedImages::nameOf(JobKind::kRender, kTag)] = entry.substr(0, entry.size() - 5);
  EXPECT_EQ(images.find(JobKind::kRender, kTag), nullptr);
  EXPECT_TRUE(store->entries.empty());
}

TEST(SharedImages, AForeignEntryIsDroppedNeverAnswered) {
  const auto store = std::make_shared<MemoryStore>();
  const SharedImages images(store);
  ASSERT_TRUE(images.store(JobKind::kRender, kOtherTag, someImage()));
  store->entries[SharedImages::nameOf(JobKind::kRender, kTag)] =
      store->entries.at(SharedImages::nameOf(JobKind::kRender, kOtherTag));
  EXPECT_EQ(images.find(JobKind::kRender, kTag), nullptr);
  EXPECT_EQ(store->entries.count(SharedImages::nameOf(JobKind::kRender, kTag)), 0u);
  EXPECT_NE(images.find(JobKind::kRender, kOtherTag), nullptr);
}

// A fit's advice is kept in an entry of its own kind, never as an image.
TEST(SharedImages, AFitsAdviceIsNotAnImage) {
  const auto store = std::make_shared<MemoryStore>();
  const SharedImages images(store);
  ASSERT_TRUE(images.store(JobKind::kFit, kTag, "{}"));
  EXPECT_EQ(store->entries.count("fit:" + kTag), 1u);
  EXPECT_EQ(store->entries.count("image:" + kTag), 0u);
  EXPECT_EQ(images.find(JobKind::kRender, kTag), nullptr);
  ASSERT_NE(images.find(JobKind::kFit, kTag), nullptr);
  EXPECT_EQ(*images.find(JobKind::kFit, kTag), "{}");
}
