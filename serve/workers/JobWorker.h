#pragma once
// figment-serve --job-worker: takes render jobs from the work queue in Redis
// (serve/workers/JobQueue.h) instead of serving HTTP, renders each on the worker pool as a request
// would be, keeps the image in Redis under the ETag an instance of this build gives it
// (serve/workers/SharedImages.h), and only then acknowledges the job. One thread per render
// worker, each with its own Redis connection and consumer name (NAME/SLOT). A job whose
// image is kept already is acknowledged without rendering; a bad request or a render the
// worker refuses (400, 500) is recorded failed with its one-line error; a worker that died
// or ran past the time limit leaves the job pending, for any consumer to take over after
// `claimAfter` s. Jobs are checked against the scenes folder's garment catalogue, as the
// server checks requests.

#include <atomic>
#include <memory>
#include <mutex>
#include <string>

#include "serve/workers/ServeOptions.h"
#include "serve/workers/WorkerPool.h"

namespace figment {
class GarmentCatalogue;
}

namespace figment::serve {

class JobQueue;
class SharedImages;
class RedisStore;
struct Job;

class JobWorker {
 public:
  // `program`: this program, started again for each render worker; `consumer`: this worker's
  // name in the consumer group (unique among the workers).
  JobWorker(const ServeOptions& options, const std::string& program, std::string consumer, double claimAfter);
  ~JobWorker();

  // Takes jobs until stop().
  void run();
  void stop() { stopping_ = true; }

 private:
  void take(int slot);
  void handle(JobQueue& queue, const SharedImages& images, const RedisStore& store, const Job& job);
  void log(const std::string& line);

  ServeOptions options_;
  std::string consumer_;
  double claimAfter_;
  std::string build_;  // Digest::buildDigest(): the ETag's second part
  std::unique_ptr<WorkerPool> pool_;
  // The scenes' garment catalogue; null when it did not read (the Mannequin's jobs alone).
  std::shared_ptr<const GarmentCatalogue> catalogue_;
  std::atomic<bool> stopping_{false};
  std::mutex logMutex_;
  std::string lastLine_;  // said once, not again by the next thread that finds the same
};

}  // namespace figment::serve
