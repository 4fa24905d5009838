#include "serve/workers/RedisConnection.h"

#include <hiredis.h>
#include <sys/time.h>

#include <cerrno>
#include <charconv>
#include <cmath>

namespace figment::serve {

namespace {

timeval toTimeval(double seconds) {
  timeval tv{};
  tv.tv_sec = static_cast<time_t>(seconds);
  tv.tv_usec = static_cast<suseconds_t>(std::lround((seconds - double(tv.tv_sec)) * 1e6));
  return tv;
}

std::optional<int> number(std::string_view text, int low, int high) {
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < low || value > high) return std::nullopt;
  return value;
}

RedisReply convert(const redisReply* reply) {
  RedisReply out;
  switch (reply->type) {
    case REDIS_REPLY_NIL:
      out.kind = RedisReply::Kind::kNil;
      break;
    case REDIS_REPLY_INTEGER:
      out.kind = RedisReply::Kind::kInteger;
      out.integer = reply->integer;
      break;
    case REDIS_REPLY_ARRAY:
      out.kind = RedisReply::Kind::kArray;
      for (size_t i = 0; i < reply->elements; ++i) out.elements.push_back(convert(reply->element[i]));
      break;
    default:
      out.kind = reply->type == REDIS_REPLY_ERROR    ? RedisReply::Kind::kError
                 : reply->type == REDIS_REPLY_STATUS ? RedisReply::Kind::kStatus
                                                     : RedisReply::Kind::kString;
      out.text.assign(reply->str, reply->len);
  }
  return out;
}

// The part of a redis:// URL after its scheme: [[USER]:PASSWORD@]HOST[:PORT][/DB].
std::string parseTcp(std::string rest, RedisAddress& address) {
  if (const size_t at = rest.rfind('@'); at != std::string::npos) {
    const std::string credentials = rest.substr(0, at);
    const size_t colon = credentials.find(':');
    if (colon == std::string::npos) return "the credentials are not [USER]:PASSWORD";
    address.user = credentials.substr(0, colon);
    address.password = credentials.substr(colon + 1);
    rest.erase(0, at + 1);
  }
  if (const size_t slash = rest.find('/'); slash != std::string::npos) {
    const std::optional<int> db = number(std::string_view(rest).substr(slash + 1), 0, 1 << 20);
    if (!db) return "the database is not a number";
    address.database = *db;
    rest.resize(slash);
  }
  if (const size_t colon = rest.rfind(':'); colon != std::string::npos) {
    const std::optional<int> port = number(std::string_view(rest).substr(colon + 1), 1, 65535);
    if (!port) return "the port is not a number from 1 to 65535";
    address.port = *port;
    rest.resize(colon);
  }
  if (rest.empty()) return "no host";
  address.host = rest;
  return "";
}

}  // namespace

std::optional<RedisAddress> RedisConnection::parse(const std::string& url, std::string& error) {
  RedisAddress address;
  std::string problem;
  if (url.rfind("redis://", 0) == 0) {
    problem = parseTcp(url.substr(8), address);
  } else if (url.rfind("unix://", 0) == 0 || url.rfind('/', 0) == 0) {
    std::string path = url.rfind('/', 0) == 0 ? url : url.substr(7);
    if (const size_t query = path.find("?db="); query != std::string::npos) {
      const std::optional<int> db = number(std::string_view(path).substr(query + 4), 0, 1 << 20);
      if (!db) problem = "the database is not a number";
      address.database = db.value_or(0);
      path.resize(query);
    }
    if (path.empty() || path[0] != '/') problem = "a Unix socket's path must be absolute";
    address.socketPath = path;
  } else {
    problem = "not redis://HOST[:PORT][/DB], unix:///PATH or /PATH";
  }
  if (problem.empty()) return address;
  error = url + ": " + problem;
  return std::nullopt;
}

RedisConnection::RedisConnection(std::string url, Options options)
    : url_(std::move(url)), options_(std::move(options)) {
  std::string error;
  address_ = parse(url_, error).value_or(RedisAddress{});
}

RedisConnection::~RedisConnection() {
  if (context_) redisFree(context_);
}

bool RedisConnection::up() const {
  std::lock_guard lock(mutex_);
  return up_;
}

bool RedisConnection::check() {
  return command({"PING"}).ok();
}

void RedisConnection::report(bool up, const std::string& why) {
  if (up == up_) return;
  up_ = up;
  if (!options_.log) return;
  options_.log(up ? "redis " + url_ + ": reachable again"
                  : "redis " + url_ + ": unreachable (" + why + "); serving from the local cache until it is back");
}

void RedisConnection::drop(const std::string& why) {
  if (context_) redisFree(context_);
  context_ = nullptr;
  nextAttempt_ = Clock::now() + std::chrono::milliseconds(std::lround(options_.retryInterval * 1000));
  report(false, why);
}

bool RedisConnection::connect() {
  const timeval timeout = toTimeval(options_.connectTimeout);
  context_ = address_.socketPath.empty() ? redisConnectWithTimeout(address_.host.c_str(), address_.port, timeout)
                                         : redisConnectUnixWithTimeout(address_.socketPath.c_str(), timeout);
  if (!context_ || context_->err) {
    drop(context_ ? context_->errstr : "cannot make a connection");
    return false;
  }
  redisSetTimeout(context_, toTimeval(options_.commandTimeout));
  std::vector<std::vector<std::string>> setup;
  if (!address_.password.empty())
    setup.push_back(address_.user.empty() ? std::vector<std::string>{"AUTH", address_.password}
                                          : std::vector<std::string>{"AUTH", address_.user, address_.password});
  if (address_.database != 0) setup.push_back({"SELECT", std::to_string(address_.database)});
  for (const std::vector<std::string>& arguments : setup) {
    RedisReply reply = send(arguments, 0);
    if (!reply.ok()) {
      drop(arguments[0] + ": " + reply.text);
      return false;
    }
  }
  report(true, "");
  return true;
}

RedisReply RedisConnection::send(const std::vector<std::string>& arguments, double blockSeconds) {
  std::vector<const char*> argv;
  std::vector<size_t> lengths;
  for (const std::string& argument : arguments) {
    argv.push_back(argument.data());
    lengths.push_back(argument.size());
  }
  if (blockSeconds > 0) redisSetTimeout(context_, toTimeval(options_.commandTimeout + blockSeconds));
  auto* reply = static_cast<redisReply*>(redisCommandArgv(context_, int(argv.size()), argv.data(), lengths.data()));
  if (!reply) {
    RedisReply broken;  // kUnreachable
    broken.text = context_->errstr[0] ? context_->errstr : "the connection broke";
    redisFree(context_);
    context_ = nullptr;
    return broken;
  }
  if (blockSeconds > 0) redisSetTimeout(context_, toTimeval(options_.commandTimeout));
  RedisReply out = convert(reply);
  freeReplyObject(reply);
  return out;
}

RedisReply RedisConnection::command(const std::vector<std::string>& arguments, double blockSeconds) {
  std::lock_guard lock(mutex_);
  // A connection that was up may have been broken since (Redis restarted): one more try
  // at once, on a new connection, before Redis counts as away.
  for (int attempt = 0; attempt < 2; ++attempt) {
    const bool wasConnected = context_ != nullptr;
    if (!context_ && (Clock::now() < nextAttempt_ || !connect())) return {};
    RedisReply reply = send(arguments, blockSeconds);
    if (reply.kind != RedisReply::Kind::kUnreachable) return reply;
    if (!wasConnected || attempt == 1) {
      drop(reply.text);
      return reply;
    }
  }
  return {};
}

}  // namespace figment::serve
