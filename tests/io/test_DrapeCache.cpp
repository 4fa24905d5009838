// The drape cache on disk: the record that goes in comes back bit for bit under the same key and
// never under another; a damaged entry is found out, removed and reported; past its
// bound the least recently used entries go; a folder that cannot be made is an error
// naming it. Over a shared store (io/SharedCacheStore.h) the folder is the first level:
// what another program stored there is found, checked and copied in; a damaged or
// foreign shared entry is dropped.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include "io/DrapeCache.h"
#include "support/IoTestSupport.h"
#include "support/MemoryStore.h"

using namespace figment;
using namespace figment::test;

using figment::test::MemoryStore;

namespace {

using Record = std::vector<unsigned char>;

// A record's bytes, about as long as a drape of `n` points makes (the cache does not read
// them: io/DrapeRecord.h does); every byte value appears, zeros and 0xff included.
Record someRecord(int n) {
  Record bytes(size_t(28 * n));
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<unsigned char>((i * 37 + n) % 256);
  return bytes;
}

}  // namespace

TEST(DrapeCache, GivesBackWhatWasStoredBitForBitAndOnlyUnderItsKey) {
  const TempDir dir;
  const DrapeCache cache(dir.path() / "figment", 1 << 20);
  const Record drape = someRecord(50);
  ASSERT_EQ(cache.store("scene A, every field", drape), "");
  std::string problem;
  const std::optional<Record> back = cache.find("scene A, every field", problem);
  ASSERT_TRUE(back);
  EXPECT_EQ(problem, "");
  EXPECT_EQ(*back, drape);
  EXPECT_FALSE(cache.find("scene A, every field but one", problem));
  EXPECT_EQ(problem, "");
}

TEST(DrapeCache, ADamagedEntryIsRemovedAndReportedNeverUsed) {
  const TempDir dir;
  const DrapeCache cache(dir.path(), 1 << 20);
  for (const std::string damage : {"flip", "truncate", "append"}) {
    ASSERT_EQ(cache.store("key", someRecord(40)), "");
    const std::filesystem::path path = cache.entryPath("key");
    std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
    if (damage == "flip") {
      file.seekp(200);
      file.put('\x7f');
      file.close();
    } else if (damage == "truncate") {
      file.close();
      std::filesystem::resize_file(path, std::filesystem::file_size(path) - 5);
    } else {
      file.seekp(0, std::ios::end);
      file.put('x');
      file.close();
    }
    std::string problem;
    EXPECT_FALSE(cache.find("key", problem)) << damage;
    EXPECT_NE(problem.find(path.string()), std::string::npos) << damage << ": " << problem;
    EXPECT_FALSE(std::filesystem::exists(path)) << damage;
  }
}

TEST(DrapeCache, PastItsBoundTheLeastRecentlyUsedGoFirst) {
  const TempDir dir;
  const Record drape = someRecord(200);  // about 5 KB an entry
  const DrapeCache cache(dir.path(), 12000);
  ASSERT_EQ(cache.store("first", drape), "");
  ASSERT_EQ(cache.store("second", drape), "");
  // Their times of use set hours apart, so the order does not depend on how finely the
  // file system keeps times: "first" the older.
  const auto now = std::filesystem::file_time_type::clock::now();
  std::filesystem::last_write_time(cache.entryPath("first"), now - std::chrono::hours(2));
  std::filesystem::last_write_time(cache.entryPath("second"), now - std::chrono::hours(1));
  std::string problem;
  ASSERT_TRUE(cache.find("first", problem));  // used: now the more recent of the two
  ASSERT_EQ(cache.store("third", drape), "");
  EXPECT_TRUE(cache.find("first", problem));
  EXPECT_FALSE(cache.find("second", problem));
  EXPECT_TRUE(cache.find("third", problem));
}

TEST(DrapeCache, AFolderThatCannotBeMadeIsAnErrorNamingIt) {
  const TempDir dir;
  const std::string file = dir.file("not-a-folder", "x");
  const DrapeCache cache(std::filesystem::path(file) / "figment", 1 << 20);
  const std::string error = cache.store("key", someRecord(5));
  EXPECT_NE(error.find(file), std::string::npos) << error;
}

TEST(DrapeCache, LivesInTheUsersCacheFolder) {
  const TempDir dir;
  {
    const ScopedEnvironment xdg("XDG_CACHE_HOME", (dir.path() / "cache").string());
    EXPECT_EQ(DrapeCache::userFolder(), dir.path() / "cache" / "figment");
  }
  const ScopedEnvironment xdg("XDG_CACHE_HOME", std::nullopt);
  const ScopedEnvironment home("HOME", (dir.path() / "home").string());
  EXPECT_EQ(DrapeCache::userFolder(), dir.path() / "home" / ".cache" / "figment");
}

TEST(DrapeCache, FindsWhatAnotherFolderStoredInTheSharedStoreAndKeepsItLocally) {
  const TempDir dir;
  const auto store = std::make_shared<MemoryStore>();
  const DrapeCache first(dir.path() / "first", 1 << 20, store);
  const DrapeCache second(dir.path() / "second", 1 << 20, store);
  const Record drape = someRecord(30);
  ASSERT_EQ(first.store("scene", drape), "");
  ASSERT_EQ(store->entries.count(first.sharedName("scene")), 1u);
  ASSERT_FALSE(std::filesystem::exists(second.entryPath("scene")));
  std::string problem;
  const std::optional<Record> back = second.find("scene", problem);
  ASSERT_TRUE(back);
  EXPECT_EQ(problem, "");
  EXPECT_EQ(*back, drape);
  EXPECT_TRUE(std::filesystem::exists(second.entryPath("scene")));  // the first level now holds it
  store->entries.clear();
  EXPECT_TRUE(second.find("scene", problem));  // read from the folder alone
  EXPECT_FALSE(second.find("another scene", problem));
  EXPECT_EQ(problem, "");
}

TEST(DrapeCache, ADamagedOrForeignSharedEntryIsDroppedNeverUsed) {
  const TempDir dir;
  const auto store = std::make_shared<MemoryStore>();
  const DrapeCache maker(dir.path() / "maker", 1 << 20, store);
  const DrapeCache reader(dir.path() / "reader", 1 << 20, store);
  ASSERT_EQ(maker.store("scene", someRecord(30)), "");
  ASSERT_EQ(maker.store("other scene", someRecord(20)), "");
  const std::string name = maker.sharedName("scene");
  for (const std::string damage : {"flip", "truncate", "foreign"}) {
    std::string bytes = store->entries.at(maker.sharedName("scene"));
    if (damage == "flip") bytes[100] ^= 0x40;
    if (damage == "truncate") bytes.resize(bytes.size() - 3);
    if (damage == "foreign") bytes = store->entries.at(maker.sharedName("other scene"));
    const std::string good = store->entries.at(name);
    store->entries[name] = bytes;
    std::string problem;
    EXPECT_FALSE(reader.find("scene", problem)) << damage;
    EXPECT_NE(problem.find(name), std::string::npos) << damage << ": " << problem;
    EXPECT_EQ(store->entries.count(name), 0u) << damage;
    EXPECT_FALSE(std::filesystem::exists(reader.entryPath("scene"))) << damage;
    store->entries[name] = good;
  }
}

TEST(DrapeCache, RemovingAnEntryRemovesItFromTheSharedStoreToo) {
  const TempDir dir;
  const auto store = std::make_shared<MemoryStore>();
  const DrapeCache cache(dir.path(), 1 << 20, store);
  ASSERT_EQ(cache.store("scene", someRecord(10)), "");
  cache.remove("scene");
  EXPECT_TRUE(store->entries.empty());
  std::string problem;
  EXPECT_FALSE(cache.find("scene", problem));
}
