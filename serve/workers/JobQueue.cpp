#include "serve/workers/JobQueue.h"

#include <cmath>
#include <cstdlib>

#include "serve/workers/Digest.h"

namespace figment::serve {

namespace {

const std::string kStream = "figment:jobs";
const std::string kRequests = "figment:jobs:requests";
const std::string kQueued = "figment:jobs:queued";
const std::string kDone = "figment:jobs:done";
const std::string kMade = "figment:jobs:made";
const std::string kFailed = "figment:jobs:failed";
constexpr size_t kBatch = 256;  // jobs added per transaction

// Adds each (key, request) of ARGV not already queued or done; a failed one added again
// is tried again. One script: a job is never recorded without its stream entry.
constexpr const char* kAddScript = R"(local added = 0
for i = 1, #ARGV, 2 do
  redis.call('HSET', KEYS[1], ARGV[i], ARGV[i + 1])
  if redis.call('HEXISTS', KEYS[5], ARGV[i]) == 0 and redis.call('HSETNX', KEYS[2], ARGV[i], ARGV[i + 1]) == 1 then
    redis.call('HDEL', KEYS[4], ARGV[i])
    redis.call('XADD', KEYS[3], '*', 'key', ARGV[i], 'request', ARGV[i + 1])
    added = added + 1
  end
end
return added)";

// Done (ARGV: key, tag, made, group, id): recorded, then acknowledged and dropped from the stream.
constexpr const char* kCompleteScript = R"(redis.call('HSET', KEYS[1], ARGV[1], ARGV[2])
if ARGV[3] == '1' then redis.call('HINCRBY', KEYS[2], ARGV[1], 1) end
redis.call('HDEL', KEYS[3], ARGV[1])
redis.call('HDEL', KEYS[4], ARGV[1])
redis.call('XACK', KEYS[5], ARGV[4], ARGV[5])
return redis.call('XDEL', KEYS[5], ARGV[5]))";

// Failed (ARGV: key, error, unused, group, id).
constexpr const char* kFailScript = R"(redis.call('HSET', KEYS[3], ARGV[1], ARGV[2])
redis.call('HDEL', KEYS[4], ARGV[1])
redis.call('XACK', KEYS[5], ARGV[4], ARGV[5])
return redis.call('XDEL', KEYS[5], ARGV[5]))";

// A stream entry [id, [field, value, ...]] as a job.
std::optional<Job> jobOf(const RedisReply& entry) {
  if (entry.kind != RedisReply::Kind::kArray || entry.elements.size() != 2) return std::nullopt;
  Job job;
  job.id = entry.elements[0].text;
  const std::vector<RedisReply>& fields = entry.elements[1].elements;
  for (size_t i = 0; i + 1 < fields.size(); i += 2) {
    if (fields[i].text == "key") job.key = fields[i + 1].text;
    if (fields[i].text == "request") job.request = fields[i + 1].text;
  }
  if (job.key.empty()) job.key = "entry " + job.id;  // a job added by hand without one: failed under this
  return job;
}

std::string milliseconds(double seconds) {
  return std::to_string(std::max(1L, std::lround(seconds * 1000)));
}

long integerOf(const RedisReply& reply) {
  return reply.kind == RedisReply::Kind::kInteger ? long(reply.integer) : 0;
}

}  // namespace

std::string JobQueue::keyOf(const std::string& request) {
  return Digest().add(request).hex();
}

std::string JobQueue::prepare() {
  const RedisReply reply = redis_.command({"XGROUP", "CREATE", kStream, kGroup, "0", "MKSTREAM"});
  if (reply.ok() || reply.text.rfind("BUSYGROUP", 0) == 0) return "";
  return "redis " + redis_.url() + ": " + (reply.text.empty() ? "unreachable" : reply.text);
}

long JobQueue::add(const std::vector<std::string>& requests, std::string& error) {
  if (error = prepare(); !error.empty()) return -1;
  long added = 0;
  for (size_t start = 0; start < requests.size(); start += kBatch) {
    std::vector<std::string> command = {"EVAL", kAddScript, "5", kRequests, kQueued, kStream, kFailed, kDone};
    for (size_t i = start; i < std::min(requests.size(), start + kBatch); ++i) {
      command.push_back(keyOf(requests[i]));
      command.push_back(requests[i]);
    }
    const RedisReply reply = redis_.command(command);
    if (reply.kind != RedisReply::Kind::kInteger) {
      error = "redis " + redis_.url() + ": " + (reply.text.empty() ? "unreachable" : reply.text);
      return -1;
    }
    added += long(reply.integer);
  }
  return added;
}

long JobQueue::deliveriesOf(const std::string& id) {
  const RedisReply reply = redis_.command({"XPENDING", kStream, kGroup, id, id, "1"});
  if (reply.kind != RedisReply::Kind::kArray || reply.elements.empty() || reply.elements[0].elements.size() < 4)
    return 1;
  return long(reply.elements[0].elements[3].integer);
}

std::optional<Job> JobQueue::claim(const std::string& consumer, double claimAfter) {
  const RedisReply reply =
      redis_.command({"XAUTOCLAIM", kStream, kGroup, consumer, milliseconds(claimAfter), claimCursor_, "COUNT", "1"});
  if (reply.kind != RedisReply::Kind::kArray || reply.elements.size() < 2) return std::nullopt;
  claimCursor_ = reply.elements[0].text.empty() ? "0-0" : reply.elements[0].text;
  for (const RedisReply& entry : reply.elements[1].elements) {
    std::optional<Job> job = jobOf(entry);
    if (!job) continue;
    job->deliveries = deliveriesOf(job->id);
    return job;
  }
  return std::nullopt;
}

std::optional<Job> JobQueue::next(const std::string& consumer, double claimAfter, double wait) {
  if (std::optional<Job> job = claim(consumer, claimAfter)) return job;
  const RedisReply reply = redis_.command(
      {"XREADGROUP", "GROUP", kGroup, consumer, "COUNT", "1", "BLOCK", milliseconds(wait), "STREAMS", kStream, ">"},
      wait);
  if (reply.kind == RedisReply::Kind::kError && reply.text.rfind("NOGROUP", 0) == 0) prepare();  // Redis lost it
  if (reply.kind != RedisReply::Kind::kArray || reply.elements.empty()) return std::nullopt;
  const RedisReply& entries = reply.elements[0].elements.size() == 2 ? reply.elements[0].elements[1] : RedisReply{};
  for (const RedisReply& entry : entries.elements)
    if (std::optional<Job> job = jobOf(entry)) return job;
  return std::nullopt;
}

bool JobQueue::finish(const Job& job, const std::string& script, const std::string& value, bool made) {
  return redis_
      .command({"EVAL", script, "5", kDone, kMade, kFailed, kQueued, kStream, job.key, value, made ? "1" : "0", kGroup,
                job.id})
      .ok();
}

bool JobQueue::complete(const Job& job, const std::string& tag, bool made) {
  return finish(job, kCompleteScript, tag, made);
}

bool JobQueue::fail(const Job& job, const std::string& error) {
  return finish(job, kFailScript, error, false);
}

std::optional<JobProgress> JobQueue::progress(std::string& error) {
  JobProgress progress;
  const RedisReply lengths = redis_.command({"EVAL",
                                             "return {redis.call('HLEN', KEYS[1]), redis.call('HLEN', KEYS[2]), "
                                             "redis.call('HLEN', KEYS[3]), redis.call('HLEN', KEYS[4])}",
                                             "4", kRequests, kQueued, kDone, kFailed});
  if (lengths.kind != RedisReply::Kind::kArray || lengths.elements.size() != 4) {
    error = "redis " + redis_.url() + ": " + (lengths.text.empty() ? "unreachable" : lengths.text);
    return std::nullopt;
  }
  progress.added = integerOf(lengths.elements[0]);
  progress.queued = integerOf(lengths.elements[1]);
  progress.done = integerOf(lengths.elements[2]);
  progress.failed = integerOf(lengths.elements[3]);
  const RedisReply pending = redis_.command({"XPENDING", kStream, kGroup});
  if (pending.kind == RedisReply::Kind::kArray && pending.elements.size() == 4) {
    progress.pending = integerOf(pending.elements[0]);
    for (const RedisReply& consumer : pending.elements[3].elements)
      if (consumer.elements.size() == 2)
        progress.consumers.emplace_back(consumer.elements[0].text, std::atol(consumer.elements[1].text.c_str()));
  }
  for (const RedisReply& made : redis_.command({"HVALS", kMade}).elements)
    progress.madeTwice += std::atol(made.text.c_str()) > 1 ? 1 : 0;
  const RedisReply failed = redis_.command({"HGETALL", kFailed});
  for (size_t i = 0; i + 1 < failed.elements.size(); i += 2) {
    const RedisReply request = redis_.command({"HGET", kRequests, failed.elements[i].text});
    progress.failures.emplace_back(request.kind == RedisReply::Kind::kString ? request.text : failed.elements[i].text,
                                   failed.elements[i + 1].text);
  }
  return progress;
}

}  // namespace figment::serve
