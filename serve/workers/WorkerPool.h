#pragma once
// The server's render workers: N worker processes, each fed by a thread of its own from
// one bounded queue of typed requests (serve/workers/JobKind.h: a render or a fit), the kind
// sent to the worker beside the request. Identical requests in flight (one kind and
// canonical text) are made once and answered alike (single flight); a full queue refuses
// at once (the server answers 503); each request has a time limit, past which its worker
// is killed; a worker that dies or is killed fails only the request it had, and is
// started again.

#include <condition_variable>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "serve/workers/JobKind.h"
#include "serve/workers/ServeOptions.h"
#include "serve/workers/WorkerProcess.h"

namespace figment::serve {

// What a worker answered (or what became of its request).
struct WorkResult {
  int status = 500;             // HTTP status: 200, 400 (a request the worker refused), 500, 502, 504
  std::string body;             // the PNG or GLB, a fit's JSON advice, or a JSON error
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

  // Has a worker make `request` (a render or a fit) and waits for it; null when the queue
  // is full. A request already in flight is joined, not queued again.
  std::shared_ptr<const WorkResult> ask(const WorkRequest& request);

  struct Load {
    int workers = 0, busy = 0, queued = 0;
    int waiting = 0;    // asks waiting for an answer: those queued or making, and those joining them
    long restarts = 0;  // workers started again after dying or being killed
  };
  Load load() const;

 private:
  struct Job;
  void run(int slot);
  std::shared_ptr<Job> next();
  WorkResult makeOn(WorkerProcess& worker, const WorkRequest& request);
  void finish(const std::shared_ptr<Job>& job, WorkResult result);

  PoolOptions options_;
  mutable std::mutex mutex_;
  std::condition_variable queued_;
  std::deque<std::shared_ptr<Job>> queue_;
  std::map<WorkRequest, std::shared_ptr<Job>> inFlight_;
  int busy_ = 0;
  int waiting_ = 0;
  long restarts_ = 0;
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace figment::serve
