#pragma once
// POST /api/render's background renders: a bounded in-memory table of jobs by the
// request's digest (its ETag, unquoted), fed to the worker pool by threads of its own so
// that no HTTP connection waits on a render. A job only tells where it stands; its image
// goes where a GET's does (the `keep` callback), so the job's result URL is a cache hit.

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "serve/workers/WorkerPool.h"

namespace figment::serve {

class RenderJobs {
 public:
  // Renders a canonical text (null: the pool's queue was full).
  using Render = std::function<std::shared_ptr<const WorkResult>(const std::string& canonical)>;
  // Keeps a finished render's answer by its id.
  using Keep = std::function<void(const std::string& id, const WorkResult& result)>;

  struct Options {
    int threads = 1;     // renders asked of the pool at once
    int waiting = 8;     // jobs queued at most beside those running: past it submit() refuses
    size_t kept = 1024;  // jobs remembered at most; the oldest finished are forgotten first
  };

  struct Status {
    std::string state;      // queued, running, done or failed
    std::string error;      // one line when failed
    std::string canonical;  // what the job renders
  };

  RenderJobs(Options options, Render render, Keep keep);
  ~RenderJobs();
  RenderJobs(const RenderJobs&) = delete;
  RenderJobs& operator=(const RenderJobs&) = delete;

  // Starts the job `id` rendering `canonical` unless it is known and not failed (then it
  // is the same job); `done` records it finished already (its image is kept). False when
  // too many jobs wait (the server answers 503).
  bool submit(const std::string& id, const std::string& canonical, bool done = false);
  std::optional<Status> find(const std::string& id) const;

 private:
  void run();
  void forgetOldest();  // with mutex_ held

  Options options_;
  Render render_;
  Keep keep_;
  mutable std::mutex mutex_;
  std::condition_variable queued_;
  std::deque<std::string> queue_;       // ids waiting
  std::map<std::string, Status> jobs_;  // by id
  std::deque<std::string> order_;       // ids, oldest first
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace figment::serve
