#pragma once
// The server's render workers: N worker processes, each fed by a thread of its own from
// one bounded queue. Identical requests in flight (one canonical text) are rendered once
// and answered alike (single flight); a full queue refuses at once (the server answers
// 503); each render has a time limit, past which its worker is killed; a worker that
// dies or is killed fails only the request it had, and is started again.

#include <condition_variable>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "serve/work/ServeOptions.h"
#include "serve/work/WorkerProcess.h"

namespace figment::serve {

// What a worker answered (or what became of its request).
struct RenderResult {
  int status = 500;             // HTTP status: 200, 400 (a request the worker refused), 500, 502, 504
  std::string body;             // the PNG, or a JSON error
  bool drapeFromCache = false;  // every drape of the scene came from the drape cache (or was kept)
  std::string drape;            // a render's: rest, restless or torn (RenderWorker::drapeState); "" else
  // Whether the answer may be kept for another request (the image caches, Redis): a fit's,
  // or a render whose drape came to rest; a restless or torn one is answered, not kept, so
  // every kept picture is of a drape at rest.
  bool keepable() const { return drape.empty() || drape == "rest"; }
};

struct PoolOptions {
  std::string program;                 // this program, for the workers
  std::vector<std::string> arguments;  // its worker-mode arguments
  int workers = 1;
  int queue = 8;          // requests waiting at most (beside those rendering)
  double timeLimit = 60;  // s per render
};

// The pool a figment-serve of these options runs (HTTP or job worker): `program` started
// again in its worker mode, with the drape cache, scenes and Redis of `options`.
PoolOptions workerPoolOptions(const ServeOptions& options, const std::string& program);

class WorkerPool {
 public:
  explicit WorkerPool(PoolOptions options);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  // Renders `canonical` (a RenderRequest's canonical text) and waits for it; null when
  // the queue is full. A request already in flight is joined, not queued again.
  std::shared_ptr<const RenderResult> render(const std::string& canonical);

  struct Load {
    int workers = 0, busy = 0, queued = 0;
    long restarts = 0;  // workers started again after dying or being killed
  };
  Load load() const;

 private:
  struct Job;
  void run(int slot);
  std::shared_ptr<Job> next();
  RenderResult renderOn(WorkerProcess& worker, const std::string& canonical);
  void finish(const std::shared_ptr<Job>& job, RenderResult result);

  PoolOptions options_;
  mutable std::mutex mutex_;
  std::condition_variable queued_;
  std::deque<std::shared_ptr<Job>> queue_;
  std::map<std::string, std::shared_ptr<Job>> inFlight_;  // by canonical text
  int busy_ = 0;
  long restarts_ = 0;
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace figment::serve
