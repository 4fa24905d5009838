// A Redis URL's parts, and a Redis that is not there: every command answers unreachable
// without waiting on it, connecting is tried again only after the retry interval, and the
// log hears of it once. (A Redis that is there: tests/serve/scenarios/test_redis.py.)

#include <gtest/gtest.h>

#include <filesystem>

#include "serve/workers/RedisConnection.h"
#include "support/TempDir.h"

using namespace figment::serve;

TEST(RedisConnection, ReadsTcpAndUnixSocketUrls) {
  std::string error;
  std::optional<RedisAddress> a = RedisConnection::parse("redis://10.0.0.5:6380/2", error);
  ASSERT_TRUE(a) << error;
  EXPECT_EQ(a->host, "10.0.0.5");
  EXPECT_EQ(a->port, 6380);
  EXPECT_EQ(a->database, 2);
  EXPECT_EQ(a->socketPath, "");
  a = RedisConnection::parse("redis://:secret@cache.internal", error);
  ASSERT_TRUE(a) << error;
  EXPECT_EQ(a->host, "cache.internal");
  EXPECT_EQ(a->port, 6379);
  EXPECT_EQ(a->password, "secret");
  EXPECT_EQ(a->user, "");
  a = RedisConnection::parse("redis://figment:pw@h:1", error);
  ASSERT_TRUE(a) << error;
  EXPECT_EQ(a->user, "figment");
  EXPECT_EQ(a->password, "pw");
  a = RedisConnection::parse("unix:///run/redis/redis.sock?db=3", error);
  ASSERT_TRUE(a) << error;
  EXPECT_EQ(a->socketPath, "/run/redis/redis.sock");
  EXPECT_EQ(a->database, 3);
  a = RedisConnection::parse("/tmp/r.sock", error);
  ASSERT_TRUE(a) << error;
  EXPECT_EQ(a->socketPath, "/tmp/r.sock");
}

TEST(RedisConnection, ABadUrlIsOneLineNamingIt) {
  for (const std::string url : {"http://h", "redis://h:0", "redis://h:http", "redis://h/x", "redis://", "unix://rel",
                                "redis://nocolon@h", "h:6379"}) {
    std::string error;
    EXPECT_FALSE(RedisConnection::parse(url, error)) << url;
    EXPECT_EQ(error.rfind(url + ": ", 0), 0u) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos);
  }
}

TEST(RedisConnection, ARedisThatIsNotThereIsUnreachableAndSaidOnce) {
  const figment::test::TempDir dir;
  std::vector<std::string> lines;
  RedisConnection::Options options;
  options.retryInterval = 3600;  // s: within the test, no second attempt to connect
  options.log = [&lines](const std::string& line) { lines.push_back(line); };
  const std::string url = (dir.path() / "no-redis.sock").string();
  RedisConnection redis(url, options);
  EXPECT_TRUE(redis.up());  // nothing tried yet
  for (int i = 0; i < 5; ++i) {
    const RedisReply reply = redis.command({"GET", "figment:image:x"});
    EXPECT_EQ(reply.kind, RedisReply::Kind::kUnreachable);
    EXPECT_FALSE(reply.ok());
  }
  EXPECT_FALSE(redis.check());
  EXPECT_FALSE(redis.up());
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find(url), std::string::npos);
  EXPECT_NE(lines[0].find("unreachable"), std::string::npos);
}
