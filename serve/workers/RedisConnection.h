#pragma once
// One connection to Redis (Debian's hiredis, synchronous), as figment-serve's shared cache
// and work queue use it. Addressed by a URL: redis://[[USER]:PASSWORD@]HOST[:PORT][/DB], or a
// Unix socket: unix:///PATH[?db=DB] or a plain absolute path. Commands are sent with
// binary-safe arguments and answered with a plain reply tree; hiredis stays in the .cpp.
//
// Redis may be away: a command then answers kUnreachable at once (connecting is tried
// again at most once a `retryInterval`), and the change is said once through `log`, in
// both directions, not on every command. A connection broken under a command (Redis
// restarted) is made again and the command sent once more, so every command sent here must
// be safe to repeat. Commands are serialised by a mutex: a thread that blocks on Redis
// (XREADGROUP BLOCK) should have a connection of its own.

#include <chrono>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

struct redisContext;

namespace figment::serve {

struct RedisReply {
  enum class Kind { kNil, kString, kInteger, kArray, kStatus, kError, kUnreachable };
  Kind kind = Kind::kUnreachable;
  std::string text;  // a string, status or error
  long long integer = 0;
  std::vector<RedisReply> elements;

  bool ok() const { return kind != Kind::kError && kind != Kind::kUnreachable; }
};

// Where a Redis URL points.
struct RedisAddress {
  std::string host;  // "" for a Unix socket
  int port = 6379;
  std::string socketPath;  // "" for TCP
  std::string user;        // "": the default user
  std::string password;    // "": no AUTH
  int database = 0;
};

class RedisConnection {
 public:
  struct Options {
    double connectTimeout = 0.5;                  // s
    double commandTimeout = 2.0;                  // s, besides a blocking command's own wait
    double retryInterval = 1.0;                   // s between attempts to connect while Redis is away
    std::function<void(const std::string&)> log;  // told when Redis goes away or comes back; may be null
  };

  // The address `url` names, or nothing with `error` saying why (one line, naming the URL).
  static std::optional<RedisAddress> parse(const std::string& url, std::string& error);

  // Connects lazily, on the first command. `url` must parse.
  RedisConnection(std::string url, Options options);
  ~RedisConnection();
  RedisConnection(const RedisConnection&) = delete;
  RedisConnection& operator=(const RedisConnection&) = delete;

  // Sends one command; `blockSeconds` is how long the command itself may wait in Redis.
  RedisReply command(const std::vector<std::string>& arguments, double blockSeconds = 0);
  // Whether the last attempt reached Redis (true before the first).
  bool up() const;
  // Reaches Redis if it can (connecting again when due); whether it is up.
  bool check();
  const std::string& url() const { return url_; }

 private:
  using Clock = std::chrono::steady_clock;
  bool connect();  // under the mutex
  RedisReply send(const std::vector<std::string>& arguments, double blockSeconds);
  void drop(const std::string& why);
  void report(bool up, const std::string& why);

  std::string url_;
  RedisAddress address_;
  Options options_;
  mutable std::mutex mutex_;
  redisContext* context_ = nullptr;
  bool up_ = true;  // as last reported
  Clock::time_point nextAttempt_{};
};

}  // namespace figment::serve
