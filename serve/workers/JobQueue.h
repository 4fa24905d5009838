#pragma once
// figment-serve's work queue on a Redis Stream (docs/deploy.md): figment-precompute adds
// render requests (canonical text) as jobs; job workers (figment-serve --job-worker) read
// them with a consumer group, store the image, then acknowledge (XACK). Delivery is at
// least once, so a job is keyed by the digest of its request and doing it twice makes the
// same image under the same key. A worker that dies leaves its job pending; another takes
// it over once it has been idle `claimAfter` (XAUTOCLAIM). A job is given up, and recorded
// as failed, when its request is bad, the render refuses it, or it has been delivered
// kMaxDeliveries times (it kills the workers that take it).
//
// Keys, under "figment:": jobs (the stream), jobs:requests (key -> request, every job
// ever added), jobs:queued (key -> request, added and not yet done or failed),
// jobs:done (key -> the image's tag), jobs:made (key -> times rendered), jobs:failed
// (key -> its one-line error). None expires: the cache's eviction never takes them.

#include <optional>
#include <string>
#include <vector>

#include "serve/workers/RedisConnection.h"

namespace figment::serve {

struct Job {
  std::string id;       // the stream entry's
  std::string key;      // the digest of the request
  std::string request;  // the request's canonical text
  long deliveries = 1;  // times delivered, this one included
};

struct JobProgress {
  long added = 0, queued = 0, done = 0, failed = 0;
  long pending = 0;  // delivered to a worker and not yet acknowledged
  long madeTwice = 0;
  std::vector<std::pair<std::string, std::string>> failures;  // request, error
  std::vector<std::pair<std::string, long>> consumers;        // name, jobs pending
};

class JobQueue {
 public:
  static constexpr long kMaxDeliveries = 5;
  static constexpr const char* kGroup = "workers";

  explicit JobQueue(RedisConnection& redis) : redis_(redis) {}

  // The key of a job for `request` (canonical text): its digest.
  static std::string keyOf(const std::string& request);

  // Makes the stream and its group where missing; "" or why not.
  std::string prepare();
  // Adds a job per request not already queued (in one transaction per batch); the number
  // added, or -1 with `error` set.
  long add(const std::vector<std::string>& requests, std::string& error);
  // The next job for `consumer`: one idle for `claimAfter` s taken over from any consumer,
  // else a new one, waiting up to `wait` s; nothing when none came (or Redis is away).
  std::optional<Job> next(const std::string& consumer, double claimAfter, double wait);
  // Records the job done with its image's `tag` (`made`: rendered now, not found made) and
  // acknowledges it; whether Redis took it.
  bool complete(const Job& job, const std::string& tag, bool made);
  // Records the job failed with its one-line error and acknowledges it.
  bool fail(const Job& job, const std::string& error);
  std::optional<JobProgress> progress(std::string& error);

 private:
  std::optional<Job> claim(const std::string& consumer, double claimAfter);
  long deliveriesOf(const std::string& id);
  bool finish(const Job& job, const std::string& script, const std::string& value, bool made);

  RedisConnection& redis_;
  std::string claimCursor_ = "0-0";
};

}  // namespace figment::serve
